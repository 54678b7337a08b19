// SPDX-License-Identifier: GPL-2.0-only
/*
 * pru_sim - pin trace, input stimulus and statistics in debugfs
 *
 * /sys/kernel/debug/pru_sim/<device>/
 *   trace      (r)  binary pin trace (sim/prusim_trace.h): the last
 *                   PRU_SIM_TRACE_LEN output changes; tools/prusim converts
 *                   it to VCD (prusim --trace-in FILE --vcd OUT)
 *              (w)  "clear" empties it; "clear N" also records only the
 *                   next N cycles (a reader slower than the simulation gets
 *                   exactly that window, nothing dropped)
 *   input/r31-0, input/r31-1, input/gpio0..gpio3
 *              (w)  a stimulus in the prusim text format ("cycle value"
 *                   lines, "repeat PERIOD"); replaces the port's input when
 *                   the file is closed.  Cycles count from that moment if a
 *                   core runs, else from the next core start.  An empty
 *                   write sets the input to 0.
 *              (r)  the number of entries, period and origin in use, and
 *                   the IEP counter at the origin
 *   stats      (r)  cycles, instructions, stalls, state and halt reason;
 *                   whether PRU outputs go through pad muxing, and how many
 *                   output changes reached no pad; OCP writes into free pages
 *   ocp_write_pause_us
 *              (rw) microseconds the thread sleeps after every OCP write,
 *                   which ends the slice (0, the default: off)
 *   stop_delay_us
 *              (rw) microseconds a core's remoteproc stop sleeps before it
 *                   halts the core (0, the default: off)
 *   pads       (rw) pad registers of the simulated board (pru_sim_board.c)
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/ctype.h>
#include <linux/debugfs.h>
#include <linux/fs.h>
#include <linux/kernel.h>
#include <linux/math64.h>
#include <linux/seq_file.h>
#include <linux/slab.h>
#include <linux/string.h>
#include <linux/time64.h>
#include <linux/uaccess.h>
#include <linux/vmalloc.h>

#include "pru_sim.h"

/* Largest stimulus text accepted through one open file. */
#define PRU_SIM_STIM_MAX	(64 << 20)

void pru_sim_trace_pin(struct pru_sim *sim, u64 cycle, unsigned int pin, bool level)
{
	struct pru_sim_trace *t = &sim->trace;
	struct prusim_trace_rec *r = &t->rec[t->head];

	if (t->until && cycle >= t->until)
		return;
	r->cycle = cycle;
	r->pin = pin;
	r->level = level;
	t->head = (t->head + 1) % PRU_SIM_TRACE_LEN;
	if (t->count < PRU_SIM_TRACE_LEN)
		t->count++;
	else
		t->dropped++;
}

/* The IEP counter now (AM335x PRU-ICSS: IEP registers at 0x2e000). */
static u32 pru_sim_iep_count(struct pru_sim *sim)
{
	u32 v = 0;

	prusim_host_read(sim->s, PRU_SIM_IEP_COUNT, &v, sizeof(v));
	return v;
}

/* A core was started: the reference point of traces and pending stimuli. */
void pru_sim_core_started(struct pru_sim *sim)
{
	unsigned int i;

	lockdep_assert_held(&sim->lock);
	sim->trace.origin = sim->s->now;
	for (i = 0; i < PRUSIM_NUM_PORTS; i++) {
		if (sim->input[i].pending_origin) {
			sim->input[i].origin = sim->s->now;
			sim->input[i].origin_iep = pru_sim_iep_count(sim);
			sim->input[i].pending_origin = false;
		}
	}
}

u32 pru_sim_input(struct pru_sim *sim, unsigned int port, u64 cycle, u64 *next_change)
{
	struct pru_sim_input *in = &sim->input[port];
	u64 next;
	u32 v;

	if (!in->stim.count || in->pending_origin || cycle < in->origin) {
		*next_change = in->stim.count && !in->pending_origin ? in->origin : PRUSIM_NEVER;
		return 0;
	}
	v = prusim_stim_value(&in->stim, cycle - in->origin, &next);
	*next_change = next == PRUSIM_NEVER ? PRUSIM_NEVER : next + in->origin;
	return v;
}

/* Whether some input pattern still has a change to come. */
bool pru_sim_inputs_pending(struct pru_sim *sim)
{
	unsigned int i;

	for (i = 0; i < PRUSIM_NUM_PORTS; i++) {
		struct pru_sim_input *in = &sim->input[i];
		u64 next;

		if (!in->stim.count || in->pending_origin)
			continue;
		if (sim->s->now < in->origin)
			return true;
		prusim_stim_value(&in->stim, sim->s->now - in->origin, &next);
		if (next != PRUSIM_NEVER)
			return true;
	}
	return false;
}

static void pru_sim_stim_free(struct prusim_stim *st)
{
	kvfree(st->cycle);
	kvfree(st->value);
	memset(st, 0, sizeof(*st));
}

void pru_sim_inputs_free(struct pru_sim *sim)
{
	unsigned int i;

	for (i = 0; i < PRUSIM_NUM_PORTS; i++)
		pru_sim_stim_free(&sim->input[i].stim);
}

/* ---- trace ---- */

struct pru_sim_snapshot {
	size_t size;
	u8 data[];
};

static int pru_sim_trace_open(struct inode *inode, struct file *file)
{
	struct pru_sim *sim = inode->i_private;
	struct pru_sim_trace *t = &sim->trace;
	struct prusim_trace_hdr *hdr;
	struct prusim_trace_rec *rec;
	struct pru_sim_snapshot *snap;
	unsigned int first, n;

	if (!(file->f_mode & FMODE_READ))
		return 0;

	snap = kvmalloc(struct_size(snap, data, sizeof(*hdr) +
				    PRU_SIM_TRACE_LEN * sizeof(*rec)), GFP_KERNEL);
	if (!snap)
		return -ENOMEM;
	hdr = (void *)snap->data;
	rec = (void *)(hdr + 1);

	mutex_lock(&sim->lock);
	memcpy(hdr->magic, PRUSIM_TRACE_MAGIC, sizeof(hdr->magic));
	hdr->version = PRUSIM_TRACE_VERSION;
	hdr->rec_size = sizeof(*rec);
	hdr->origin = t->origin;
	hdr->count = t->count;
	hdr->dropped = t->dropped;
	hdr->end = t->until ? min(sim->s->now, t->until) : sim->s->now;
	first = (t->head + PRU_SIM_TRACE_LEN - t->count) % PRU_SIM_TRACE_LEN;
	n = min_t(unsigned int, t->count, PRU_SIM_TRACE_LEN - first);
	memcpy(rec, &t->rec[first], n * sizeof(*rec));
	memcpy(rec + n, t->rec, (t->count - n) * sizeof(*rec));
	snap->size = sizeof(*hdr) + t->count * sizeof(*rec);
	mutex_unlock(&sim->lock);

	file->private_data = snap;
	return 0;
}

static ssize_t pru_sim_trace_read(struct file *file, char __user *buf, size_t len,
				  loff_t *ppos)
{
	struct pru_sim_snapshot *snap = file->private_data;

	if (!snap)
		return -EBADF;
	return simple_read_from_buffer(buf, len, ppos, snap->data, snap->size);
}

static ssize_t pru_sim_trace_write(struct file *file, const char __user *ubuf, size_t len,
				   loff_t *ppos)
{
	struct pru_sim *sim = file_inode(file)->i_private;
	char buf[32] = { };
	char *arg;
	u64 window = 0;

	if (len > sizeof(buf) - 1 || copy_from_user(buf, ubuf, len))
		return -EINVAL;
	arg = strim(buf);
	if (strncmp(arg, "clear", 5) || (arg[5] && !isspace(arg[5])))
		return -EINVAL;
	arg = skip_spaces(arg + 5);
	if (*arg && (kstrtou64(arg, 0, &window) || !window))
		return -EINVAL;

	mutex_lock(&sim->lock);
	sim->trace.head = 0;
	sim->trace.count = 0;
	sim->trace.dropped = 0;
	sim->trace.until = window ? sim->s->now + window : 0;
	mutex_unlock(&sim->lock);
	return len;
}

static int pru_sim_trace_release(struct inode *inode, struct file *file)
{
	kvfree(file->private_data);
	return 0;
}

static const struct file_operations pru_sim_trace_fops = {
	.owner = THIS_MODULE,
	.open = pru_sim_trace_open,
	.read = pru_sim_trace_read,
	.write = pru_sim_trace_write,
	.release = pru_sim_trace_release,
	.llseek = default_llseek,
};

/* ---- input stimulus ---- */

/**
 * struct pru_sim_input_file - a stimulus being written
 * @in: the port
 * @text: what was written so far
 * @len: bytes in @text
 * @cap: size of @text
 * @checked: @text up to here consists of complete lines already checked
 */
struct pru_sim_input_file {
	struct pru_sim_input *in;
	char *text;
	size_t len;
	size_t cap;
	size_t checked;
};

static int pru_sim_input_open(struct inode *inode, struct file *file)
{
	struct pru_sim_input_file *f;

	f = kzalloc(sizeof(*f), GFP_KERNEL);
	if (!f)
		return -ENOMEM;
	f->in = inode->i_private;
	file->private_data = f;
	return 0;
}

static int pru_sim_input_grow(struct pru_sim_input_file *f, size_t need)
{
	size_t cap = max3(need, 2 * f->cap, (size_t)PAGE_SIZE);
	char *text;

	if (need <= f->cap)
		return 0;
	text = kvmalloc(cap, GFP_KERNEL);
	if (!text)
		return -ENOMEM;
	if (f->len)
		memcpy(text, f->text, f->len);
	kvfree(f->text);
	f->text = text;
	f->cap = cap;
	return 0;
}

/* Count the entries of @len bytes of stimulus text; -errno with @err set. */
static int pru_sim_stim_count(const char *text, size_t len, char *err, size_t errlen)
{
	return prusim_stim_parse(text, len, NULL, err, errlen);
}

static ssize_t pru_sim_input_write(struct file *file, const char __user *ubuf, size_t len,
				   loff_t *ppos)
{
	struct pru_sim_input_file *f = file->private_data;
	char err[PRUSIM_REASON_LEN];
	size_t end;
	int ret;

	if (len > PRU_SIM_STIM_MAX - f->len)
		return -EFBIG;
	ret = pru_sim_input_grow(f, f->len + len);
	if (ret)
		return ret;
	if (copy_from_user(f->text + f->len, ubuf, len))
		return -EFAULT;

	/*
	 * Check the complete lines this write finishes, so that bad input
	 * fails here.  A piece may be wrong only out of context (a repeat
	 * line far from the entries): then check everything up to here.
	 */
	end = f->len + len;
	while (end > f->checked && f->text[end - 1] != '\n')
		end--;
	if (end > f->checked &&
	    pru_sim_stim_count(f->text + f->checked, end - f->checked, err, sizeof(err)) < 0) {
		ret = pru_sim_stim_count(f->text, end, err, sizeof(err));
		if (ret < 0) {
			dev_err(f->in->sim->dev, "input %u: %s\n", f->in->port, err);
			return ret;
		}
	}
	f->checked = max(f->checked, end);
	f->len += len;
	return len;
}

/* Parse the whole text into a new pattern and put it in place. */
static int pru_sim_input_install(struct pru_sim_input_file *f)
{
	struct pru_sim_input *in = f->in;
	struct pru_sim *sim = in->sim;
	struct prusim_stim st = { }, old;
	char err[PRUSIM_REASON_LEN];
	int n;

	n = pru_sim_stim_count(f->text, f->len, err, sizeof(err));
	if (n < 0)
		goto bad;
	if (n) {
		st.cycle = kvmalloc_array(n, sizeof(*st.cycle), GFP_KERNEL);
		st.value = kvmalloc_array(n, sizeof(*st.value), GFP_KERNEL);
		if (!st.cycle || !st.value) {
			pru_sim_stim_free(&st);
			return -ENOMEM;
		}
		st.count = n;
		n = prusim_stim_parse(f->text, f->len, &st, err, sizeof(err));
		if (n < 0) {
			pru_sim_stim_free(&st);
			goto bad;
		}
	}

	mutex_lock(&sim->lock);
	old = in->stim;
	in->stim = st;
	in->pending_origin = !prusim_active(sim->s);
	in->origin = sim->s->now;
	in->origin_iep = pru_sim_iep_count(sim);
	/* The simulator caches inputs until their announced next change. */
	prusim_input_changed(sim->s, in->port);
	mutex_unlock(&sim->lock);

	pru_sim_stim_free(&old);
	pru_sim_kick_thread(sim);
	return 0;

bad:
	dev_err(sim->dev, "input %u: %s; input unchanged\n", in->port, err);
	return n;
}

static int pru_sim_input_release(struct inode *inode, struct file *file)
{
	struct pru_sim_input_file *f = file->private_data;
	struct dentry *dentry = file->f_path.dentry;

	/*
	 * Opened only to read, or nothing written: nothing changes.  debugfs
	 * calls release even after the files were removed (the device was
	 * unbound with this file open): then the simulator is gone, and the
	 * text is dropped.  Holding the file keeps the removal waiting.
	 */
	if (f->len && !debugfs_file_get(dentry)) {
		pru_sim_input_install(f);
		debugfs_file_put(dentry);
	}
	kvfree(f->text);
	kfree(f);
	return 0;
}

static ssize_t pru_sim_input_read(struct file *file, char __user *buf, size_t len,
				  loff_t *ppos)
{
	struct pru_sim_input_file *f = file->private_data;
	struct pru_sim_input *in = f->in;
	char text[128];
	int n;

	mutex_lock(&in->sim->lock);
	n = scnprintf(text, sizeof(text), "entries %zu period %llu origin %llu iep %u%s\n",
		      in->stim.count, in->stim.period, in->origin, in->origin_iep,
		      in->pending_origin ? " (next start)" : "");
	mutex_unlock(&in->sim->lock);
	return simple_read_from_buffer(buf, len, ppos, text, n);
}

static const struct file_operations pru_sim_input_fops = {
	.owner = THIS_MODULE,
	.open = pru_sim_input_open,
	.read = pru_sim_input_read,
	.write = pru_sim_input_write,
	.release = pru_sim_input_release,
	.llseek = noop_llseek,
};

/* ---- statistics ---- */

static const char * const pru_sim_state_name[] = {
	[PRUSIM_DISABLED] = "disabled",
	[PRUSIM_RUNNING] = "running",
	[PRUSIM_SLEEPING] = "sleeping",
	[PRUSIM_HALTED] = "halted",
	[PRUSIM_STOPPED] = "stopped",
};

static int pru_sim_stats_show(struct seq_file *m, void *v)
{
	struct pru_sim *sim = m->private;
	unsigned int i;

	mutex_lock(&sim->lock);
	seq_printf(m, "cycles %llu\n", sim->s->now);
	seq_printf(m, "host_ns %llu\n", sim->host_ns);
	for (i = 0; i < PRUSIM_NUM_CORES; i++) {
		struct prusim_status st;

		prusim_get_status(sim->s, i, &st);
		seq_printf(m, "pru%u state %s pc 0x%x instructions %llu stalls %llu reason %s\n",
			   i, pru_sim_state_name[st.state], st.pc * 4, st.insns, st.stalls,
			   st.reason[0] ? st.reason : "-");
	}
	seq_printf(m, "trace_events %u trace_dropped %llu trace_origin %llu trace_until %llu\n",
		   sim->trace.count, sim->trace.dropped, sim->trace.origin, sim->trace.until);
	seq_printf(m, "pads %s unmuxed_writes %llu\n", sim->pads_live ? "checked" : "unchecked",
		   sim->unmuxed_writes);
	seq_printf(m, "ocp_writes_to_free_pages %llu\n", sim->ocp_free_writes);
	seq_puts(m, "routes");
	for (i = 0; i < PRUSIM_NUM_EVENTS; i++)
		if (sim->mapped & BIT_ULL(i))
			seq_printf(m, " %u:%u:%u", i, sim->route_ch[i], sim->route_host[i]);
	seq_putc(m, '\n');
	mutex_unlock(&sim->lock);

	spin_lock_irq(&sim->stat_lock);
	seq_printf(m, "irq_latency last %llu max %llu mean %llu count %llu\n",
		   sim->lat_last, sim->lat_max,
		   sim->lat_count ? div64_u64(sim->lat_sum, sim->lat_count) : 0,
		   sim->lat_count);
	spin_unlock_irq(&sim->stat_lock);
	return 0;
}
DEFINE_SHOW_ATTRIBUTE(pru_sim_stats);

/* ---- knobs: widen races for tests ---- */

/* Longest pause or delay: 1 s (the sleeps are uninterruptible). */
#define PRU_SIM_KNOB_MAX_US	USEC_PER_SEC

/* A knob's file has the knob (a u32 of struct pru_sim) as its data. */
static int pru_sim_knob_get(void *data, u64 *val)
{
	*val = READ_ONCE(*(u32 *)data);
	return 0;
}

static int pru_sim_knob_set(void *data, u64 val)
{
	if (val > PRU_SIM_KNOB_MAX_US)
		return -ERANGE;
	WRITE_ONCE(*(u32 *)data, (u32)val);
	return 0;
}
DEFINE_DEBUGFS_ATTRIBUTE(pru_sim_knob_fops, pru_sim_knob_get, pru_sim_knob_set, "%llu\n");

void pru_sim_debugfs_init(struct pru_sim *sim, struct dentry *root)
{
	static const char * const names[PRUSIM_NUM_PORTS] = {
		[PRUSIM_PORT_R31(0)] = "r31-0",
		[PRUSIM_PORT_R31(1)] = "r31-1",
		[PRUSIM_PORT_GPIO(0)] = "gpio0",
		[PRUSIM_PORT_GPIO(1)] = "gpio1",
		[PRUSIM_PORT_GPIO(2)] = "gpio2",
		[PRUSIM_PORT_GPIO(3)] = "gpio3",
	};
	struct dentry *input;
	unsigned int i;

	sim->debugfs = debugfs_create_dir(dev_name(sim->dev), root);

	debugfs_create_file("trace", 0600, sim->debugfs, sim, &pru_sim_trace_fops);
	debugfs_create_file("stats", 0400, sim->debugfs, sim, &pru_sim_stats_fops);
	debugfs_create_file_unsafe("ocp_write_pause_us", 0600, sim->debugfs,
				   &sim->ocp_write_pause_us, &pru_sim_knob_fops);
	debugfs_create_file_unsafe("stop_delay_us", 0600, sim->debugfs,
				   &sim->stop_delay_us, &pru_sim_knob_fops);
	input = debugfs_create_dir("input", sim->debugfs);
	for (i = 0; i < PRUSIM_NUM_PORTS; i++) {
		sim->input[i].sim = sim;
		sim->input[i].port = i;
		debugfs_create_file(names[i], 0600, input, &sim->input[i], &pru_sim_input_fops);
	}
}
