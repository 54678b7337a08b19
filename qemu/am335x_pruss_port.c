/* SPDX-License-Identifier: GPL-2.0-only */
/*
 * AM335x PRU-ICSS for prukit's test VM: prukit's test port - the pin
 * trace, input stimulus, statistics and knobs as files the guest reads and
 * writes (see am335x_pruss.c, sim/prusim_port.h and prukit's
 * Documentation/qemu-pruss.rst).
 */

#include "qemu/osdep.h"
#include "qemu/cutils.h"
#include "qemu/log.h"
#include "trace.h"

#include "am335x_pruss_internal.h"

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
static uint32_t G_GNUC_PRINTF(2, 3) port_reply(AM335xPrussState *p,
                                               const char *fmt, ...)
{
    va_list ap;
    int n;

    va_start(ap, fmt);
    n = vsnprintf((char *)p->buf, PORT_BUF_SIZE, fmt, ap);
    va_end(ap);
    return MIN((uint32_t)MAX(n, 0), PORT_BUF_SIZE - 1);
}

/* Appends to the reply being built at *@len */
void G_GNUC_PRINTF(3, 4) port_add(AM335xPrussState *p, uint32_t *len,
                                  const char *fmt, ...)
{
    va_list ap;
    int n;

    if (*len >= PORT_BUF_SIZE - 1) {
        return;
    }
    va_start(ap, fmt);
    n = vsnprintf((char *)p->buf + *len, PORT_BUF_SIZE - *len, fmt, ap);
    va_end(ap);
    *len = MIN(*len + MAX(n, 0), PORT_BUF_SIZE - 1);
}

static uint32_t port_trace(AM335xPrussState *p)
{
    struct prusim_trace_hdr hdr;
    uint32_t first, n;
    uint8_t *rec = p->buf + sizeof(hdr);

    memset(&hdr, 0, sizeof(hdr));
    memcpy(hdr.magic, PRUSIM_TRACE_MAGIC, sizeof(hdr.magic));
    hdr.version = PRUSIM_TRACE_VERSION;
    hdr.rec_size = sizeof(struct prusim_trace_rec);
    hdr.origin = p->trace_origin;
    hdr.count = p->trace_count;
    hdr.dropped = p->trace_dropped;
    hdr.end = p->trace_until ? MIN(p->s->now, p->trace_until) : p->s->now;
    memcpy(p->buf, &hdr, sizeof(hdr));
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

static uint32_t port_stats(AM335xPrussState *p)
{
    uint64_t enabled = (uint64_t)pruss_icss_read32(p, ICSS_INTC_ESR(1)) << 32 |
                       pruss_icss_read32(p, ICSS_INTC_ESR(0));
    uint8_t cmr[PRUSIM_NUM_EVENTS], hmr[12];
    uint32_t len = 0;
    unsigned int i;
    int64_t held = p->hold_since ? pruss_now_ns(p) - p->hold_since : 0;

    prusim_host_read(p->s, ICSS_INTC_CMR(0), cmr, sizeof(cmr));
    prusim_host_read(p->s, ICSS_INTC_HMR(0), hmr, sizeof(hmr));
    port_add(p, &len, "cycles %" PRIu64 "\n", p->s->now);
    /* every core waits for the ARM: simulated time stands still */
    port_add(p, &len, "idle %s\n", p->runnable ? "no" : "yes");
    port_add(p, &len, "host_ns %" PRIu64 "\n", p->host_ns);
    for (i = 0; i < PRUSIM_NUM_CORES; i++) {
        struct prusim_status st;

        prusim_get_status(p->s, i, &st);
        port_add(p, &len, "pru%u state %s pc 0x%x instructions %" PRIu64
                 " stalls %" PRIu64 " reason %s\n", i, state_name[st.state],
                 st.pc * 4, st.insns, st.stalls,
                 st.reason[0] ? st.reason : "-");
    }
    port_add(p, &len, "icss %s resets %" PRIu64 " ram_words %u"
             " cores_at_last_reset %s %s\n",
             pruss_icss_in_reset(p) ? "reset" : "running", p->icss_resets,
             icss_ram_words(p), state_name[p->reset_states[0]],
             state_name[p->reset_states[1]]);
    port_add(p, &len, "trace_events %u trace_dropped %" PRIu64
             " trace_origin %" PRIu64
             " trace_until %" PRIu64 "\n", p->trace_count, p->trace_dropped,
             p->trace_origin, p->trace_until);
    port_add(p, &len, "pads checked unmuxed_writes %" PRIu64 "\n",
             p->unmuxed_writes);
    port_add(p, &len, "gpio_unpinned_writes %" PRIu64 "\n",
             p->gpio_unpinned);
    port_add(p, &len, "gpio_gated_writes %" PRIu64 " gated_banks",
             p->gpio_gated);
    for (i = 0; i < PRUSIM_GPIO_BANKS; i++) {
        if (pruss_gpio_gated(p, i)) {
            port_add(p, &len, " gpio%u", i);
        }
    }
    port_add(p, &len, "\n");
    port_add(p, &len, "gpio_clocks");
    for (i = 0; i < PRUSIM_GPIO_BANKS; i++) {
        port_add(p, &len, " gpio%u %s", i,
                 pruss_gpio_clocked(p, i) ? "on" : "off");
    }
    port_add(p, &len, " gatings %" PRIu64 "\n", p->gpio_clock_gatings);
    port_add(p, &len, "unmuxed_outputs");
    for (i = 0; i < 64; i++) {
        if ((p->unmuxed_seen >> i) & 1) {
            port_add(p, &len, " pru%u_r30_%u", i / 32, i % 32);
        }
    }
    for (i = 0; i < 32 * PRUSIM_GPIO_BANKS; i++) {
        if ((p->gpio_unmuxed_seen[i / 32] >> (i % 32)) & 1) {
            port_add(p, &len, " gpio%u_%u", i / 32, i % 32);
        }
    }
    port_add(p, &len, "\n");
    port_add(p, &len, "routes");
    for (i = 0; i < PRUSIM_NUM_EVENTS; i++) {
        unsigned int ch = cmr[i] & 0xf;

        if (((enabled | p->in_service) >> i) & 1) {
            port_add(p, &len, " %u:%u:%u", i, ch,
                     ch < PRUSIM_NUM_CHANNELS ? hmr[ch] & 0xf : 0);
        }
    }
    port_add(p, &len, "\n");
    port_add(p, &len, "irq_latency last %" PRIu64 " max %" PRIu64
             " mean %" PRIu64
             " count %" PRIu64 "\n", p->lat_last, p->lat_max,
             p->lat_count ? p->lat_sum / p->lat_count : 0, p->lat_count);
    port_add(p, &len, "holds %" PRIu64 " held_ns %" PRIu64
             " held_max_ns %" PRIu64
             " hold_expired %" PRIu64 " hold_cap_ms %u hold_mode %u\n",
             p->holds, p->hold_ns + held,
             MAX(p->hold_max_ns, (uint64_t)held), p->hold_expired,
             p->hold_cap_ms, p->hold_mode);
    port_add(p, &len, "ocp_writes %" PRIu64 " ocp_write_delay %u"
             " ocp_write_flight_us %u ddr_jitter %u"
             " ocp_drained %" PRIu64 "\n",
             p->ocp_writes, p->ocp_write_delay, p->ocp_write_flight_us,
             p->jitter ? p->ddr_jitter : 0, p->ocp_drained);
    port_add(p, &len, "ocp_errors %" PRIu64 "%s%s\n", p->ocp_errors,
             p->ocp_errors ? " last " : "", p->ocp_errors ? p->ocp_err : "");
    port_add(p, &len, "jitter %u slices %" PRIu64 " pauses %" PRIu64
             " pause_ns %" PRIu64 "\n", p->jitter, p->jitter_slices,
             p->jitter_pauses, p->jitter_pause_ns);
    port_add(p, &len, "clock %s virtual_ns %" PRId64 " lockstep_runs %" PRIu64
             "\n", p->lockstep ? "lockstep" : "thread",
             qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL), p->lockstep_runs);
    port_add(p, &len, "unmodelled %" PRIu64 "\n", p->unimp);
    port_add(p, &len, "unmodelled_last %s\n",
             p->unimp ? p->unimp_last : "-");
    return len;
}

static uint32_t port_input_info(AM335xPrussState *p, unsigned int port)
{
    PrussInput *in = &p->input[port];

    return port_reply(p, "entries %zu period %" PRIu64 " origin %" PRIu64
                      " iep %u%s\n",
                      in->stim.count, in->stim.period, in->origin,
                      in->origin_iep,
                      in->pending_origin ? " (next start)" : "");
}

static int port_read(AM335xPrussState *p, unsigned int file, uint32_t *len)
{
    switch (file) {
    case PF_TRACE:
        *len = port_trace(p);
        return 0;
    case PF_STATS:
        *len = port_stats(p);
        return 0;
    case PF_PADS:
        *len = pruss_pads_text(p);
        return 0;
    case PF_OCP_WRITE_PAUSE_US:
        *len = port_reply(p, "%u\n", p->ocp_write_pause_us);
        return 0;
    case PF_FREEZE:
        *len = port_reply(p, "%u\n", p->freeze);
        return 0;
    case PF_JITTER:
        *len = port_reply(p, "%u\n", p->jitter);
        return 0;
    case PF_HOLD_MODE:
        *len = port_reply(p, "%u\n", p->hold_mode);
        return 0;
    case PF_OCP_WRITE_DELAY:
        *len = port_reply(p, "%u\n", p->ocp_write_delay);
        return 0;
    case PF_OCP_WRITE_FLIGHT_US:
        *len = port_reply(p, "%u\n", p->ocp_write_flight_us);
        return 0;
    case PF_DDR_JITTER:
        *len = port_reply(p, "%u\n", p->ddr_jitter);
        return 0;
    }
    if (file >= PF_INPUT && file < PF_NUM) {
        *len = port_input_info(p, file - PF_INPUT);
        return 0;
    }
    return -EINVAL;
}

/* The written text, NUL terminated, trimmed; NULL if it holds a NUL */
static char *port_text(AM335xPrussState *p, uint32_t len, char *dst,
                       size_t size)
{
    if (len >= size || memchr(p->buf, 0, len)) {
        return NULL;
    }
    memcpy(dst, p->buf, len);
    dst[len] = 0;
    return g_strstrip(dst);
}

static int port_write_trace(AM335xPrussState *p, uint32_t len, uint32_t *reply)
{
    char text[64], *arg;
    uint64_t window = 0;
    bool first;

    arg = port_text(p, len, text, sizeof(text));
    if (!arg || strncmp(arg, "clear", 5) ||
        (arg[5] && !g_ascii_isspace(arg[5]))) {
        *reply = port_reply(p, "trace: write \"clear\", \"clear CYCLES\" or "
                            "\"clear first\"");
        return -EINVAL;
    }
    arg = g_strchug(arg + 5);
    first = !strcmp(arg, "first");
    if (*arg && !first) {
        if (arg[0] == '-' || qemu_strtou64(arg, NULL, 0, &window) ||
            !window) {
            *reply = port_reply(p, "trace: bad window \"%s\"", arg);
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
static int port_write_pads(AM335xPrussState *p, uint32_t len, uint32_t *reply)
{
    const char *end;
    char text[64], *arg;
    uint64_t off, val;

    arg = port_text(p, len, text, sizeof(text));
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
    p->pad[(off - 0x800) / 4] = val;
    p->pad_writes++;
    pruss_pads_changed(p);
    return 0;
bad:
    *reply = port_reply(p,
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

static int port_write_knob(AM335xPrussState *p, uint32_t *knob, uint32_t max,
                           uint32_t len, uint32_t *reply)
{
    char text[32], *arg;
    uint64_t v;

    arg = port_text(p, len, text, sizeof(text));
    if (!arg || arg[0] == '-' || qemu_strtou64(arg, NULL, 0, &v)) {
        *reply = port_reply(p, "a number from 0 to %u", max);
        return -EINVAL;
    }
    if (v > max) {
        *reply = port_reply(p, "at most %u", max);
        return -ERANGE;
    }
    *knob = v;
    return 0;
}

static int port_write(AM335xPrussState *p, unsigned int file, uint32_t len,
                      uint32_t *reply)
{
    int ret;

    switch (file) {
    case PF_TRACE:
        return port_write_trace(p, len, reply);
    case PF_PADS:
        return port_write_pads(p, len, reply);
    case PF_OCP_WRITE_PAUSE_US:
        return port_write_knob(p, &p->ocp_write_pause_us, KNOB_MAX_US, len,
                               reply);
    case PF_FREEZE:
        return port_write_knob(p, &p->freeze, 1, len, reply);
    case PF_JITTER:
        ret = port_write_knob(p, &p->jitter, UINT32_MAX, len, reply);
        if (!ret) {
            pruss_jitter_seed(p);
        }
        return ret;
    case PF_HOLD_MODE:
        return port_write_knob(p, &p->hold_mode, HOLD_NONE, len, reply);
    case PF_OCP_WRITE_DELAY:
        ret = port_write_knob(p, &p->ocp_write_delay, OCP_WRITE_DELAY_MAX,
                              len, reply);
        if (!ret) {
            prusim_set_ocp_write_delay(p->s, p->ocp_write_delay);
        }
        return ret;
    case PF_OCP_WRITE_FLIGHT_US:
        return port_write_knob(p, &p->ocp_write_flight_us, KNOB_MAX_US, len,
                               reply);
    case PF_DDR_JITTER:
        ret = port_write_knob(p, &p->ddr_jitter, DDR_JITTER_MAX, len, reply);
        if (!ret) {
            pruss_jitter_seed(p);
        }
        return ret;
    }
    return -EINVAL;
}

/* Check the complete lines a piece of stimulus text finishes */
static int port_append(AM335xPrussState *p, PrussStage *st, uint32_t len,
                       uint32_t *reply)
{
    char err[PRUSIM_REASON_LEN];
    size_t end, staged = 0;
    unsigned int i;
    int ret;

    for (i = 0; i < PORT_HANDLES; i++) {
        staged += p->stage[i].len;
    }
    if (len > STIM_MAX - staged) {
        *reply = port_reply(p, "input %u: more than %u MiB of text staged",
                            st->port, STIM_MAX >> 20);
        return -EFBIG;
    }
    if (st->len + len > st->cap) {
        st->cap = MAX(st->len + len, 2 * st->cap);
        st->text = g_realloc(st->text, st->cap);
    }
    memcpy(st->text + st->len, p->buf, len);
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
            *reply = port_reply(p, "input %u: %s", st->port, err);
            return ret;
        }
    }
    st->checked = MAX(st->checked, end);
    st->len += len;
    return 0;
}

static int port_install(AM335xPrussState *p, PrussStage *stg, uint32_t *reply)
{
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
        *reply = port_reply(p, "input %u: %s; input unchanged", stg->port, err);
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

void pruss_stage_free(PrussStage *st)
{
    g_free(st->text);
    memset(st, 0, sizeof(*st));
}

/* Run a command of the test port.  BQL and lock held. */
static void port_command(AM335xPrussState *p, uint32_t cmd)
{
    unsigned int op = PRUSIM_TEST_PORT_CMD_OP(cmd);
    unsigned int file = PRUSIM_TEST_PORT_CMD_FILE(cmd);
    unsigned int h = PRUSIM_TEST_PORT_CMD_HANDLE(cmd);
    uint32_t len = MIN(p->port_len, (uint32_t)PORT_BUF_SIZE), reply = 0;
    PrussStage *st = h < PORT_HANDLES ? &p->stage[h] : NULL;
    int status = 0;
    unsigned int i;

    switch (op) {
    case PRUSIM_TEST_PORT_OP_LIST:
        for (i = 0; i < PF_NUM; i++) {
            port_add(p, &reply, "%s %s %s\n", port_file_name[i],
                     i == PF_STATS ? "0400" : "0600",
                     i >= PF_INPUT ? "staged" : "snapshot");
        }
        break;
    case PRUSIM_TEST_PORT_OP_READ:
        status = port_read(p, file, &reply);
        break;
    case PRUSIM_TEST_PORT_OP_WRITE:
        status = file >= PF_INPUT ? -EINVAL : port_write(p, file, len, &reply);
        break;
    case PRUSIM_TEST_PORT_OP_OPEN:
        status = -EMFILE;
        if (file < PF_INPUT || file >= PF_NUM) {
            status = -EINVAL;
            break;
        }
        for (i = 0; i < PORT_HANDLES; i++) {
            if (!p->stage[i].used) {
                p->stage[i].used = true;
                p->stage[i].port = file - PF_INPUT;
                p->port_handle = i;
                status = 0;
                break;
            }
        }
        break;
    case PRUSIM_TEST_PORT_OP_APPEND:
        status = st && st->used ? port_append(p, st, len, &reply) : -EBADF;
        break;
    case PRUSIM_TEST_PORT_OP_CLOSE:
    case PRUSIM_TEST_PORT_OP_DROP:
        if (!st || !st->used) {
            status = -EBADF;
            break;
        }
        if (op == PRUSIM_TEST_PORT_OP_CLOSE && st->len) {
            status = port_install(p, st, &reply);
        }
        pruss_stage_free(st);
        break;
    default:
        status = -EINVAL;
        break;
    }
    p->port_status = -status;     /* the register: a positive errno */
    p->port_len = reply;
    trace_am335x_pruss_port(op, file, status, reply);
}

static uint64_t port_read_reg(void *opaque, hwaddr off, unsigned int size)
{
    AM335xPrussState *p = opaque;

    switch (off) {
    case PRUSIM_TEST_PORT_REG_ID:
        return PRUSIM_TEST_PORT_ID;
    case PRUSIM_TEST_PORT_REG_VERSION:
        return PRUSIM_TEST_PORT_VERSION;
    case PRUSIM_TEST_PORT_REG_STATUS:
        return p->port_status;
    case PRUSIM_TEST_PORT_REG_LEN:
        return p->port_len;
    case PRUSIM_TEST_PORT_REG_BUFSIZE:
        return PORT_BUF_SIZE;
    case PRUSIM_TEST_PORT_REG_HANDLE:
        return p->port_handle;
    }
    qemu_log_mask(LOG_GUEST_ERROR,
                  "am335x-pruss: test port read at 0x%" HWADDR_PRIx "\n", off);
    return 0;
}

static void port_write_reg(void *opaque, hwaddr off, uint64_t val,
                           unsigned int size)
{
    AM335xPrussState *p = opaque;

    switch (off) {
    case PRUSIM_TEST_PORT_REG_LEN:
        p->port_len = val;
        return;
    case PRUSIM_TEST_PORT_REG_CMD:
        pruss_lock(p);
        port_command(p, val);
        pruss_update_irqs(p);
        pruss_unlock(p, true);
        return;
    }
    qemu_log_mask(LOG_GUEST_ERROR,
                  "am335x-pruss: test port write at 0x%" HWADDR_PRIx "\n",
                  off);
}

const MemoryRegionOps pruss_port_ops = {
    .read = port_read_reg,
    .write = port_write_reg,
    .endianness = DEVICE_LITTLE_ENDIAN,
    .valid = { .min_access_size = 4, .max_access_size = 4 },
};
