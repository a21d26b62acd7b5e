/*
 * insncount: a QEMU TCG plugin that counts the guest instructions a program executes and
 * prints "insns: N" when it exits. Used by tests/bench/insncount/arm-insncount (which
 * builds it) for the ARM instruction counts in docs/performance.md.
 *
 * How it counts: when QEMU translates a block of guest code (a translation block, TB), the
 * plugin asks for one inline 64-bit add of the block's instruction count to a counter,
 * performed every time the block runs. No callback into C per instruction or per block, so
 * the program runs at nearly the emulator's normal speed, and the count is the same on
 * every run of the same binary with the same inputs: it does not depend on the host.
 * One counter for all vCPUs (in qemu-user, all guest threads), added to without atomics:
 * count single-threaded programs.
 *
 * Debian 12's qemu-user (7.2) implements plugin API version 1 but ships no qemu-plugin.h,
 * so the handful of entry points used here are declared below, as documented in QEMU's
 * "QEMU TCG Plugins" API reference (include/qemu/qemu-plugin.h of QEMU 7.2).
 *
 * Build: cc -O2 -shared -fPIC -o libinsncount.so insncount.c
 * Run:   qemu-aarch64 -L /usr/aarch64-linux-gnu -plugin ./libinsncount.so -d plugin PROGRAM
 */
#include <inttypes.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* ---- the part of QEMU's plugin API (version 1) this plugin uses ------------------------ */
#define EXPORTED __attribute__((visibility("default")))

typedef uint64_t qemu_plugin_id_t;
typedef struct qemu_info_t qemu_info_t; /* only passed through, never read here */
struct qemu_plugin_tb;                  /* opaque: a block being translated */

enum qemu_plugin_op { QEMU_PLUGIN_INLINE_ADD_U64 };

typedef void (*qemu_plugin_vcpu_tb_trans_cb_t)(qemu_plugin_id_t id, struct qemu_plugin_tb *tb);
typedef void (*qemu_plugin_udata_cb_t)(qemu_plugin_id_t id, void *userdata);

void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id, qemu_plugin_vcpu_tb_trans_cb_t cb);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb *tb);
void qemu_plugin_register_vcpu_tb_exec_inline(struct qemu_plugin_tb *tb, enum qemu_plugin_op op,
                                              void *ptr, uint64_t imm);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id, qemu_plugin_udata_cb_t cb, void *userdata);
void qemu_plugin_outs(const char *string);

/* QEMU refuses a plugin that does not say which API version it was written for. */
EXPORTED int qemu_plugin_version = 1;

/* ---- the plugin ------------------------------------------------------------------------ */
static uint64_t executed;

/* Called once per translated block: add its length each time it runs. */
static void on_translate(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
    (void)id;
    qemu_plugin_register_vcpu_tb_exec_inline(tb, QEMU_PLUGIN_INLINE_ADD_U64, &executed,
                                             (uint64_t)qemu_plugin_tb_n_insns(tb));
}

static void on_exit(qemu_plugin_id_t id, void *userdata)
{
    (void)id;
    (void)userdata;
    char line[48];
    snprintf(line, sizeof line, "insns: %" PRIu64 "\n", executed);
    qemu_plugin_outs(line); /* to QEMU's log: stderr, given -d plugin */
}

EXPORTED int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info, int argc, char **argv)
{
    (void)info;
    (void)argv;
    if (argc != 0) {
        fprintf(stderr, "insncount: takes no arguments\n");
        return -1;
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_translate);
    qemu_plugin_register_atexit_cb(id, on_exit, NULL);
    return 0;
}
