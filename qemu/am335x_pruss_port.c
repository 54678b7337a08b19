/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * prukit's test port (TYPE_AM335X_PRUSS_PORT) for the AM335x PRU-ICSS in
 * prukit's test VM: the pin trace, input stimulus, statistics and knobs as
 * files the guest reads and writes (see am335x_pruss.c, sim/prusim_port.h
 * and prukit's Documentation/qemu-pruss.rst).  Not a block of the SoC: an
 * instrument with a link to the PRU-ICSS, whose lock its commands take.
 * Registers at 0x5f000000, a buffer both sides read and write at
 * 0x5f800000.
 */

#include "qemu/osdep.h"
#include "qemu/cutils.h"
#include "qemu/log.h"
#include "qapi/error.h"
#include "hw/qdev-properties.h"
#include "migration/vmstate.h"
#include "trace.h"

#include "am335x_pruss_internal.h"
#include "prusim/am335x_pins.h"

/* ------------------------------------------------------------------ */
/* Test port: files                                                    */

enum port_file {
    PF_TRACE,
    PF_STATS,
    PF_PADS,
    PF_OCP_WRITE_PAUSE_US,
    PF_FREEZE,
    PF_JITTER,
    PF_HOLD_MODE,
    PF_OCP_WRITE_DELAY,
    PF_OCP_WRITE_FLIGHT_US,
    PF_DDR_JITTER,
    PF_INPUT,               /* PF_INPUT + port: input/<name> */
    PF_NUM = PF_INPUT + PRUSIM_NUM_PORTS,
};

static const char *const port_file_name[PF_NUM] = {
    [PF_TRACE] = "trace",
    [PF_STATS] = "stats",
    [PF_PADS] = "pads",
    [PF_OCP_WRITE_PAUSE_US] = "ocp_write_pause_us",
    [PF_FREEZE] = "freeze",
    [PF_JITTER] = "jitter",
    [PF_HOLD_MODE] = "hold_mode",
    [PF_OCP_WRITE_DELAY] = "ocp_write_delay",
    [PF_OCP_WRITE_FLIGHT_US] = "ocp_write_flight_us",
    [PF_DDR_JITTER] = "ddr_jitter",
    [PF_INPUT + PRUSIM_PORT_R31(0)] = "input/r31-0",
    [PF_INPUT + PRUSIM_PORT_R31(1)] = "input/r31-1",
    [PF_INPUT + PRUSIM_PORT_GPIO(0)] = "input/gpio0",
    [PF_INPUT + PRUSIM_PORT_GPIO(1)] = "input/gpio1",
    [PF_INPUT + PRUSIM_PORT_GPIO(2)] = "input/gpio2",
    [PF_INPUT + PRUSIM_PORT_GPIO(3)] = "input/gpio3",
};

/* Reply text; returns its length (truncated to the buffer) */
static uint32_t G_GNUC_PRINTF(2, 3) port_reply(AM335xPrussPortState *t,
                                               const char *fmt, ...)
{
    va_list ap;
    int n;

    va_start(ap, fmt);
    n = vsnprintf((char *)t->buf, PORT_BUF_SIZE, fmt, ap);
    va_end(ap);
    return MIN((uint32_t)MAX(n, 0), PORT_BUF_SIZE - 1);
}

/* Appends to the reply being built at *@len */
static void G_GNUC_PRINTF(3, 4) port_add(AM335xPrussPortState *t,
                                         uint32_t *len, const char *fmt, ...)
{
    va_list ap;
    int n;

    if (*len >= PORT_BUF_SIZE - 1) {
        return;
    }
    va_start(ap, fmt);
    n = vsnprintf((char *)t->buf + *len, PORT_BUF_SIZE - *len, fmt, ap);
    va_end(ap);
    *len = MIN(*len + MAX(n, 0), PORT_BUF_SIZE - 1);
}

static uint32_t port_trace(AM335xPrussPortState *t)
{
    AM335xPrussState *p = t->pruss;
    struct prusim_trace_hdr hdr;
    uint32_t first, n;
    uint8_t *rec = t->buf + sizeof(hdr);

    memset(&hdr, 0, sizeof(hdr));
    memcpy(hdr.magic, PRUSIM_TRACE_MAGIC, sizeof(hdr.magic));
    hdr.version = PRUSIM_TRACE_VERSION;
    hdr.rec_size = sizeof(struct prusim_trace_rec);
    hdr.origin = p->trace_origin;
    hdr.count = p->trace_count;
    hdr.dropped = p->trace_dropped;
    hdr.end = p->trace_until ? MIN(p->s->now, p->trace_until) : p->s->now;
    memcpy(t->buf, &hdr, sizeof(hdr));
    first = (p->trace_head + TRACE_LEN - p->trace_count) % TRACE_LEN;
    n = MIN(p->trace_count, TRACE_LEN - first);
    memcpy(rec, &p->trace[first], n * sizeof(*p->trace));
    memcpy(rec + n * sizeof(*p->trace), p->trace,
           (p->trace_count - n) * sizeof(*p->trace));
    return sizeof(hdr) + p->trace_count * sizeof(*p->trace);
}

static const char *const state_name[] = {
    [PRUSIM_DISABLED] = "disabled",
    [PRUSIM_RUNNING] = "running",
    [PRUSIM_SLEEPING] = "sleeping",
    [PRUSIM_HALTED] = "halted",
    [PRUSIM_STOPPED] = "stopped",
};

/* The PRU-ICSS's RAMs, as the ARM sees them: instruction, data, shared */
static const struct {
    uint32_t off;
    uint32_t size;
} icss_rams[] = {
    { 0x34000, 0x2000 }, { 0x38000, 0x2000 },
    { 0x00000, 0x2000 }, { 0x02000, 0x2000 }, { 0x10000, 0x3000 },
};

/* How many 32-bit words of the RAMs are not 0 (a reset clears them all) */
static unsigned int icss_ram_words(AM335xPrussState *p)
{
    uint32_t chunk[64];
    unsigned int i, n = 0;
    uint32_t off, w;

    for (i = 0; i < ARRAY_SIZE(icss_rams); i++) {
        for (off = 0; off < icss_rams[i].size; off += sizeof(chunk)) {
            prusim_host_read(p->s, icss_rams[i].off + off, chunk,
                             sizeof(chunk));
            for (w = 0; w < ARRAY_SIZE(chunk); w++) {
                n += chunk[w] != 0;
            }
        }
    }
    return n;
}

static uint32_t port_stats(AM335xPrussPortState *t)
{
    AM335xPrussState *p = t->pruss;
    uint64_t enabled = (uint64_t)pruss_icss_read32(p, ICSS_INTC_ESR(1)) << 32 |
                       pruss_icss_read32(p, ICSS_INTC_ESR(0));
    uint8_t cmr[PRUSIM_NUM_EVENTS], hmr[12];
    uint32_t len = 0;
    uint64_t gatings = 0;
    unsigned int i;
    int64_t held = p->hold_since ? pruss_now_ns(p) - p->hold_since : 0;

    prusim_host_read(p->s, ICSS_INTC_CMR(0), cmr, sizeof(cmr));
    prusim_host_read(p->s, ICSS_INTC_HMR(0), hmr, sizeof(hmr));
    port_add(t, &len, "cycles %" PRIu64 "\n", p->s->now);
    /* every core waits for the ARM: simulated time stands still */
    port_add(t, &len, "idle %s\n", p->runnable ? "no" : "yes");
    port_add(t, &len, "host_ns %" PRIu64 "\n", p->host_ns);
    for (i = 0; i < PRUSIM_NUM_CORES; i++) {
        struct prusim_status st;

        prusim_get_status(p->s, i, &st);
        port_add(t, &len, "pru%u state %s pc 0x%x instructions %" PRIu64
                 " stalls %" PRIu64 " reason %s\n", i, state_name[st.state],
                 st.pc * 4, st.insns, st.stalls,
                 st.reason[0] ? st.reason : "-");
    }
    port_add(t, &len, "icss %s resets %" PRIu64 " ram_words %u"
             " cores_at_last_reset %s %s\n",
             pruss_icss_in_reset(p) ? "reset" : "running", p->icss_resets,
             icss_ram_words(p), state_name[p->reset_states[0]],
             state_name[p->reset_states[1]]);
    port_add(t, &len, "trace_events %u trace_dropped %" PRIu64
             " trace_origin %" PRIu64
             " trace_until %" PRIu64 "\n", p->trace_count, p->trace_dropped,
             p->trace_origin, p->trace_until);
    port_add(t, &len, "pads checked unmuxed_writes %" PRIu64 "\n",
             p->unmuxed_writes);
    port_add(t, &len, "gpio_unpinned_writes %" PRIu64 "\n",
             p->gpio_unpinned);
    port_add(t, &len, "gpio_gated_writes %" PRIu64 " gated_banks",
             p->gpio_gated);
    for (i = 0; i < PRUSIM_GPIO_BANKS; i++) {
        if (pruss_gpio_gated(p, i)) {
            port_add(t, &len, " gpio%u", i);
        }
    }
    port_add(t, &len, "\n");
    port_add(t, &len, "gpio_clocks");
    for (i = 0; i < PRUSIM_GPIO_BANKS; i++) {
        port_add(t, &len, " gpio%u %s", i,
                 pruss_gpio_clocked(p, i) ? "on" : "off");
        gatings += p->gpio[i]->clock_gatings;
    }
    port_add(t, &len, " gatings %" PRIu64 "\n", gatings);
    port_add(t, &len, "unmuxed_outputs");
    for (i = 0; i < 64; i++) {
        if ((p->unmuxed_seen >> i) & 1) {
            port_add(t, &len, " pru%u_r30_%u", i / 32, i % 32);
        }
    }
    for (i = 0; i < 32 * PRUSIM_GPIO_BANKS; i++) {
        if ((p->gpio[i / 32]->unpinned_seen >> (i % 32)) & 1) {
            port_add(t, &len, " gpio%u_%u", i / 32, i % 32);
        }
    }
    port_add(t, &len, "\n");
    port_add(t, &len, "routes");
    for (i = 0; i < PRUSIM_NUM_EVENTS; i++) {
        unsigned int ch = cmr[i] & 0xf;

        if (((enabled | p->in_service) >> i) & 1) {
            port_add(t, &len, " %u:%u:%u", i, ch,
                     ch < PRUSIM_NUM_CHANNELS ? hmr[ch] & 0xf : 0);
        }
    }
    port_add(t, &len, "\n");
    port_add(t, &len, "irq_latency last %" PRIu64 " max %" PRIu64
             " mean %" PRIu64
             " count %" PRIu64 "\n", p->lat_last, p->lat_max,
             p->lat_count ? p->lat_sum / p->lat_count : 0, p->lat_count);
    port_add(t, &len, "holds %" PRIu64 " held_ns %" PRIu64
             " held_max_ns %" PRIu64
             " hold_expired %" PRIu64 " hold_cap_ms %u hold_mode %u\n",
             p->holds, p->hold_ns + held,
             MAX(p->hold_max_ns, (uint64_t)held), p->hold_expired,
             p->hold_cap_ms, p->hold_mode);
    port_add(t, &len, "ocp_writes %" PRIu64 " ocp_write_delay %u"
             " ocp_write_flight_us %u ddr_jitter %u"
             " ocp_drained %" PRIu64 "\n",
             p->ocp_writes, p->ocp_write_delay, p->ocp_write_flight_us,
             p->jitter ? p->ddr_jitter : 0, p->ocp_drained);
    port_add(t, &len, "ocp_errors %" PRIu64 "%s%s\n", p->ocp_errors,
             p->ocp_errors ? " last " : "", p->ocp_errors ? p->ocp_err : "");
    port_add(t, &len, "jitter %u slices %" PRIu64 " pauses %" PRIu64
             " pause_ns %" PRIu64 "\n", p->jitter, p->jitter_slices,
             p->jitter_pauses, p->jitter_pause_ns);
    port_add(t, &len, "clock %s virtual_ns %" PRId64 " lockstep_runs %" PRIu64
             "\n", p->lockstep ? "lockstep" : "thread",
             qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL), p->lockstep_runs);
    port_add(t, &len, "unmodelled %" PRIu64 "\n", p->unimp);
    port_add(t, &len, "unmodelled_last %s\n",
             p->unimp ? p->unimp_last : "-");
    return len;
}

static uint32_t port_input_info(AM335xPrussPortState *t, unsigned int port)
{
    AM335xPrussState *p = t->pruss;
    PrussInput *in = &p->input[port];

    return port_reply(t, "entries %zu period %" PRIu64 " origin %" PRIu64
                      " iep %u%s\n",
                      in->stim.count, in->stim.period, in->origin,
                      in->origin_iep,
                      in->pending_origin ? " (next start)" : "");
}

/* "pads": every pad not at its reset value and every pad of a PRU output */
static uint32_t port_pads(AM335xPrussPortState *t)
{
    AM335xPadsState *pads = t->pruss->pads;
    uint32_t len = 0;
    unsigned int i, r;

    for (i = 0; i < PADS_NUM; i++) {
        uint32_t off = 0x800 + 4 * i, pad = pad_reg(pads, i);
        bool listed = pad != PAD_RESET;

        for (r = 0; r < ARRAY_SIZE(am335x_r30_pads); r++) {
            listed |= am335x_r30_pads[r].offset == off;
        }
        if (!listed) {
            continue;
        }
        port_add(t, &len, "0x%03x 0x%02x", off, pad);
        for (r = 0; r < ARRAY_SIZE(am335x_r30_pads); r++) {
            const struct am335x_pin_row *row = &am335x_r30_pads[r];

            if (row->offset == off) {
                port_add(t, &len, " pru%u_r30_%u %s", row->unit, row->bit,
                         (pad & PAD_MODE) == row->mode ? "muxed" : "unmuxed");
            }
        }
        port_add(t, &len, "\n");
    }
    return len;
}

static int port_read(AM335xPrussPortState *t, unsigned int file,
                     uint32_t *len)
{
    AM335xPrussState *p = t->pruss;
    switch (file) {
    case PF_TRACE:
        *len = port_trace(t);
        return 0;
    case PF_STATS:
        *len = port_stats(t);
        return 0;
    case PF_PADS:
        *len = port_pads(t);
        return 0;
    case PF_OCP_WRITE_PAUSE_US:
        *len = port_reply(t, "%u\n", p->ocp_write_pause_us);
        return 0;
    case PF_FREEZE:
        *len = port_reply(t, "%u\n", p->freeze);
        return 0;
    case PF_JITTER:
        *len = port_reply(t, "%u\n", p->jitter);
        return 0;
    case PF_HOLD_MODE:
        *len = port_reply(t, "%u\n", p->hold_mode);
        return 0;
    case PF_OCP_WRITE_DELAY:
        *len = port_reply(t, "%u\n", p->ocp_write_delay);
        return 0;
    case PF_OCP_WRITE_FLIGHT_US:
        *len = port_reply(t, "%u\n", p->ocp_write_flight_us);
        return 0;
    case PF_DDR_JITTER:
        *len = port_reply(t, "%u\n", p->ddr_jitter);
        return 0;
    }
    if (file >= PF_INPUT && file < PF_NUM) {
        *len = port_input_info(t, file - PF_INPUT);
        return 0;
    }
    return -EINVAL;
}

/* The written text, NUL terminated, trimmed; NULL if it holds a NUL */
static char *port_text(AM335xPrussPortState *t, uint32_t len, char *dst,
                       size_t size)
{
    if (len >= size || memchr(t->buf, 0, len)) {
        return NULL;
    }
    memcpy(dst, t->buf, len);
    dst[len] = 0;
    return g_strstrip(dst);
}

static int port_write_trace(AM335xPrussPortState *t, uint32_t len,
                            uint32_t *reply)
{
    AM335xPrussState *p = t->pruss;
    char text[64], *arg;
    uint64_t window = 0;
    bool first;

    arg = port_text(t, len, text, sizeof(text));
    if (!arg || strncmp(arg, "clear", 5) ||
        (arg[5] && !g_ascii_isspace(arg[5]))) {
        *reply = port_reply(t, "trace: write \"clear\", \"clear CYCLES\" or "
                            "\"clear first\"");
        return -EINVAL;
    }
    arg = g_strchug(arg + 5);
    first = !strcmp(arg, "first");
    if (*arg && !first) {
        if (arg[0] == '-' || qemu_strtou64(arg, NULL, 0, &window) ||
            !window) {
            *reply = port_reply(t, "trace: bad window \"%s\"", arg);
            return -EINVAL;
        }
    }
    p->trace_first = first;
    p->trace_head = 0;
    p->trace_count = 0;
    p->trace_dropped = 0;
    p->trace_until = !window ? 0 :
                     window > UINT64_MAX - p->s->now ? UINT64_MAX :
                     p->s->now + window;
    return 0;
}

/* "0xOFFSET 0xVALUE": set a pad as config-pin does (value at most 0x7f) */
static int port_write_pads(AM335xPrussPortState *t, uint32_t len,
                           uint32_t *reply)
{
    AM335xPrussState *p = t->pruss;
    const char *end;
    char text[64], *arg;
    uint64_t off, val;

    arg = port_text(t, len, text, sizeof(text));
    if (!arg) {
        goto bad;
    }
    if (qemu_strtou64(arg, &end, 0, &off) || !g_ascii_isspace(*end)) {
        goto bad;
    }
    arg = g_strchug(arg + (end - arg));
    if (arg[0] == '-' || qemu_strtou64(arg, NULL, 0, &val) || off < 0x800 ||
        off >= 0x800 + PADS_SIZE || off & 3 || val > PAD_MASK) {
        goto bad;
    }
    am335x_pads_set(p->pads, (off - 0x800) / 4, val);
    return 0;
bad:
    *reply = port_reply(t,
                        "pads: write \"0xOFFSET 0xVALUE\", "
                        "a pad 0x800..0x%x and a value up to 0x%x",
                        0x800 + PADS_SIZE - 4, PAD_MASK);
    return -EINVAL;
}

/* jitter: a new seed (or off), the same slices and pauses for the same one */
void pruss_jitter_seed(AM335xPrussState *p)
{
    g_rand_set_seed(p->rng, p->jitter);
    /* the DDR's jitter: from the same seed, only while the knob is on */
    prusim_set_ddr_jitter(p->s, p->jitter ? p->ddr_jitter : 0, p->jitter);
}

static int port_write_knob(AM335xPrussPortState *t, uint32_t *knob,
                           uint32_t max, uint32_t len, uint32_t *reply)
{
    char text[32], *arg;
    uint64_t v;

    arg = port_text(t, len, text, sizeof(text));
    if (!arg || arg[0] == '-' || qemu_strtou64(arg, NULL, 0, &v)) {
        *reply = port_reply(t, "a number from 0 to %u", max);
        return -EINVAL;
    }
    if (v > max) {
        *reply = port_reply(t, "at most %u", max);
        return -ERANGE;
    }
    *knob = v;
    return 0;
}

static int port_write(AM335xPrussPortState *t, unsigned int file, uint32_t len,
                      uint32_t *reply)
{
    AM335xPrussState *p = t->pruss;
    int ret;

    switch (file) {
    case PF_TRACE:
        return port_write_trace(t, len, reply);
    case PF_PADS:
        return port_write_pads(t, len, reply);
    case PF_OCP_WRITE_PAUSE_US:
        return port_write_knob(t, &p->ocp_write_pause_us, KNOB_MAX_US, len,
                               reply);
    case PF_FREEZE:
        return port_write_knob(t, &p->freeze, 1, len, reply);
    case PF_JITTER:
        ret = port_write_knob(t, &p->jitter, UINT32_MAX, len, reply);
        if (!ret) {
            pruss_jitter_seed(p);
        }
        return ret;
    case PF_HOLD_MODE:
        return port_write_knob(t, &p->hold_mode, HOLD_NONE, len, reply);
    case PF_OCP_WRITE_DELAY:
        ret = port_write_knob(t, &p->ocp_write_delay, OCP_WRITE_DELAY_MAX,
                              len, reply);
        if (!ret) {
            prusim_set_ocp_write_delay(p->s, p->ocp_write_delay);
        }
        return ret;
    case PF_OCP_WRITE_FLIGHT_US:
        return port_write_knob(t, &p->ocp_write_flight_us, KNOB_MAX_US, len,
                               reply);
    case PF_DDR_JITTER:
        ret = port_write_knob(t, &p->ddr_jitter, DDR_JITTER_MAX, len, reply);
        if (!ret) {
            pruss_jitter_seed(p);
        }
        return ret;
    }
    return -EINVAL;
}

/* Check the complete lines a piece of stimulus text finishes */
static int port_append(AM335xPrussPortState *t, PrussStage *st, uint32_t len,
                       uint32_t *reply)
{
    char err[PRUSIM_REASON_LEN];
    size_t end, staged = 0;
    unsigned int i;
    int ret;

    for (i = 0; i < PORT_HANDLES; i++) {
        staged += t->stage[i].len;
    }
    if (len > STIM_MAX - staged) {
        *reply = port_reply(t, "input %u: more than %u MiB of text staged",
                            st->port, STIM_MAX >> 20);
        return -EFBIG;
    }
    if (st->len + len > st->cap) {
        st->cap = MAX(st->len + len, 2 * st->cap);
        st->text = g_realloc(st->text, st->cap);
    }
    memcpy(st->text + st->len, t->buf, len);
    end = st->len + len;
    while (end > st->checked && st->text[end - 1] != '\n') {
        end--;
    }
    if (end > st->checked &&
        prusim_stim_parse(st->text + st->checked, end - st->checked, NULL,
                          err, sizeof(err)) < 0) {
        /* a piece may be wrong only out of context: check it all */
        ret = prusim_stim_parse(st->text, end, NULL, err, sizeof(err));
        if (ret < 0) {
            *reply = port_reply(t, "input %u: %s", st->port, err);
            return ret;
        }
    }
    st->checked = MAX(st->checked, end);
    st->len += len;
    return 0;
}

static int port_install(AM335xPrussPortState *t, PrussStage *stg,
                        uint32_t *reply)
{
    AM335xPrussState *p = t->pruss;
    PrussInput *in = &p->input[stg->port];
    struct prusim_stim st = { 0 };
    char err[PRUSIM_REASON_LEN];
    int n;

    n = prusim_stim_parse(stg->text, stg->len, NULL, err, sizeof(err));
    if (n > 0) {
        st.cycle = g_new(uint64_t, n);
        st.value = g_new(uint32_t, n);
        st.count = n;
        n = prusim_stim_parse(stg->text, stg->len, &st, err, sizeof(err));
    }
    if (n < 0) {
        pruss_stim_free(&st);
        *reply = port_reply(t, "input %u: %s; input unchanged", stg->port, err);
        return n;
    }
    pruss_stim_free(&in->stim);
    in->stim = st;
    in->pending_origin = !prusim_active(p->s);
    in->origin = p->s->now;
    in->origin_iep = pruss_iep_count(p);
    /* the simulator caches inputs until their announced next change */
    prusim_input_changed(p->s, stg->port);
    p->runnable = true;
    return 0;
}

static void port_stage_free(PrussStage *st)
{
    g_free(st->text);
    memset(st, 0, sizeof(*st));
}

/* Run a command of the test port.  BQL and lock held. */
static void port_command(AM335xPrussPortState *t, uint32_t cmd)
{
    unsigned int op = PRUSIM_TEST_PORT_CMD_OP(cmd);
    unsigned int file = PRUSIM_TEST_PORT_CMD_FILE(cmd);
    unsigned int h = PRUSIM_TEST_PORT_CMD_HANDLE(cmd);
    uint32_t len = MIN(t->len, (uint32_t)PORT_BUF_SIZE), reply = 0;
    PrussStage *st = h < PORT_HANDLES ? &t->stage[h] : NULL;
    int status = 0;
    unsigned int i;

    switch (op) {
    case PRUSIM_TEST_PORT_OP_LIST:
        for (i = 0; i < PF_NUM; i++) {
            port_add(t, &reply, "%s %s %s\n", port_file_name[i],
                     i == PF_STATS ? "0400" : "0600",
                     i >= PF_INPUT ? "staged" : "snapshot");
        }
        break;
    case PRUSIM_TEST_PORT_OP_READ:
        status = port_read(t, file, &reply);
        break;
    case PRUSIM_TEST_PORT_OP_WRITE:
        status = file >= PF_INPUT ? -EINVAL : port_write(t, file, len, &reply);
        break;
    case PRUSIM_TEST_PORT_OP_OPEN:
        status = -EMFILE;
        if (file < PF_INPUT || file >= PF_NUM) {
            status = -EINVAL;
            break;
        }
        for (i = 0; i < PORT_HANDLES; i++) {
            if (!t->stage[i].used) {
                t->stage[i].used = true;
                t->stage[i].port = file - PF_INPUT;
                t->handle = i;
                status = 0;
                break;
            }
        }
        break;
    case PRUSIM_TEST_PORT_OP_APPEND:
        status = st && st->used ? port_append(t, st, len, &reply) : -EBADF;
        break;
    case PRUSIM_TEST_PORT_OP_CLOSE:
    case PRUSIM_TEST_PORT_OP_DROP:
        if (!st || !st->used) {
            status = -EBADF;
            break;
        }
        if (op == PRUSIM_TEST_PORT_OP_CLOSE && st->len) {
            status = port_install(t, st, &reply);
        }
        port_stage_free(st);
        break;
    default:
        status = -EINVAL;
        break;
    }
    t->status = -status;     /* the register: a positive errno */
    t->len = reply;
    trace_am335x_pruss_port(op, file, status, reply);
}

static uint64_t port_read_reg(void *opaque, hwaddr off, unsigned int size)
{
    AM335xPrussPortState *t = opaque;

    switch (off) {
    case PRUSIM_TEST_PORT_REG_ID:
        return PRUSIM_TEST_PORT_ID;
    case PRUSIM_TEST_PORT_REG_VERSION:
        return PRUSIM_TEST_PORT_VERSION;
    case PRUSIM_TEST_PORT_REG_STATUS:
        return t->status;
    case PRUSIM_TEST_PORT_REG_LEN:
        return t->len;
    case PRUSIM_TEST_PORT_REG_BUFSIZE:
        return PORT_BUF_SIZE;
    case PRUSIM_TEST_PORT_REG_HANDLE:
        return t->handle;
    }
    qemu_log_mask(LOG_GUEST_ERROR,
                  "am335x-pruss: test port read at 0x%" HWADDR_PRIx "\n", off);
    return 0;
}

static void port_write_reg(void *opaque, hwaddr off, uint64_t val,
                           unsigned int size)
{
    AM335xPrussPortState *t = opaque;
    AM335xPrussState *p = t->pruss;

    switch (off) {
    case PRUSIM_TEST_PORT_REG_LEN:
        t->len = val;
        return;
    case PRUSIM_TEST_PORT_REG_CMD:
        pruss_lock(p);
        port_command(t, val);
        pruss_update_irqs(p);
        pruss_unlock(p, true);
        return;
    }
    qemu_log_mask(LOG_GUEST_ERROR,
                  "am335x-pruss: test port write at 0x%" HWADDR_PRIx "\n",
                  off);
}

static const MemoryRegionOps port_ops = {
    .read = port_read_reg,
    .write = port_write_reg,
    .endianness = DEVICE_LITTLE_ENDIAN,
    .valid = { .min_access_size = 4, .max_access_size = 4 },
};

/* ------------------------------------------------------------------ */
/* Device                                                              */

static void port_reset_enter(Object *obj, ResetType type)
{
    AM335xPrussPortState *t = AM335X_PRUSS_PORT(obj);
    unsigned int i;

    pruss_lock(t->pruss);
    for (i = 0; i < PORT_HANDLES; i++) {
        port_stage_free(&t->stage[i]);
    }
    pruss_unlock(t->pruss, false);
    t->status = 0;
    t->len = 0;
    t->handle = 0;
}

static void port_realize(DeviceState *dev, Error **errp)
{
    AM335xPrussPortState *t = AM335X_PRUSS_PORT(dev);
    SysBusDevice *sbd = SYS_BUS_DEVICE(dev);
    Error *err = NULL;

    if (!t->pruss) {
        error_setg(errp, "link pruss is not set");
        return;
    }
    memory_region_init_io(&t->mr, OBJECT(t), &port_ops, t,
                          "am335x-pruss-port", PORT_SIZE);
    sysbus_init_mmio(sbd, &t->mr);
    memory_region_init_ram(&t->buf_mr, OBJECT(t), "am335x-pruss-port.buf",
                           PORT_BUF_SIZE, &err);
    if (err) {
        error_propagate(errp, err);
        return;
    }
    t->buf = memory_region_get_ram_ptr(&t->buf_mr);
    sysbus_init_mmio(sbd, &t->buf_mr);
}

static void port_unrealize(DeviceState *dev)
{
    AM335xPrussPortState *t = AM335X_PRUSS_PORT(dev);
    unsigned int i;

    for (i = 0; i < PORT_HANDLES; i++) {
        port_stage_free(&t->stage[i]);
    }
}

static Property port_props[] = {
    DEFINE_PROP_LINK("pruss", AM335xPrussPortState, pruss, TYPE_AM335X_PRUSS,
                     AM335xPrussState *),
    DEFINE_PROP_END_OF_LIST(),
};

/* A test instrument of the PRU-ICSS, which cannot be saved. */
static const VMStateDescription vmstate_am335x_pruss_port = {
    .name = TYPE_AM335X_PRUSS_PORT,
    .unmigratable = 1,
};

static void port_class_init(ObjectClass *klass, void *data)
{
    DeviceClass *dc = DEVICE_CLASS(klass);
    ResettableClass *rc = RESETTABLE_CLASS(klass);

    dc->realize = port_realize;
    dc->unrealize = port_unrealize;
    rc->phases.enter = port_reset_enter;
    dc->vmsd = &vmstate_am335x_pruss_port;
    dc->desc = "prukit's test port for the AM335x PRU-ICSS";
    dc->user_creatable = false;
    device_class_set_props(dc, port_props);
}

static const TypeInfo port_info = {
    .name = TYPE_AM335X_PRUSS_PORT,
    .parent = TYPE_SYS_BUS_DEVICE,
    .instance_size = sizeof(AM335xPrussPortState),
    .class_init = port_class_init,
};

static void port_register_types(void)
{
    type_register_static(&port_info);
}
type_init(port_register_types)
