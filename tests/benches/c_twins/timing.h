/*
 * The self-timing main every C twin includes last (docs/native-engine.md §11.3), after it has
 * defined `twin_cycle` (one cycle of the workload on its global instance `m`) and `twin_check`
 * (the checked variable as an integer: a BOOL as 0 or 1, a REAL as its IEEE bits).
 *
 * It times `twin_cycle` exactly as `median_ns` in scan_report.rs times the engines: the
 * repetitions are calibrated to a 20 ms batch, 15 batches are timed with
 * clock_gettime(CLOCK_MONOTONIC), and the median is reported. A compiler barrier between
 * cycles keeps the compiler from merging cycles or keeping the instance in registers across
 * them. Before timing, it runs three cycles from the initial values and keeps the checked
 * variable, which the bench compares with both engines'. It prints one line of JSON:
 * {"ns_per_cycle": 123.456, "check": 42}
 */
#ifndef RIVET_TWIN_TIMING_H
#define RIVET_TWIN_TIMING_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

/* Batches timed; the median is reported. */
#define TWIN_BATCHES 15
/* Roughly how long one batch runs, in nanoseconds. */
#define TWIN_BATCH_NS 20000000.0
/* How long the calibration runs, in nanoseconds. */
#define TWIN_CALIBRATION_NS 5000000.0

/* A barrier the compiler cannot see through: memory is read and written behind its back. */
#define TWIN_BARRIER() __asm__ volatile("" ::: "memory")

static double twin_now_ns(void)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)now.tv_sec * 1e9 + (double)now.tv_nsec;
}

static int twin_compare(const void *a, const void *b)
{
    double x = *(const double *)a;
    double y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(void)
{
    for (int cycle = 0; cycle < 3; cycle++) {
        twin_cycle();
        TWIN_BARRIER();
    }
    long long check = twin_check();

    double start = twin_now_ns();
    uint64_t calls = 0;
    while (twin_now_ns() - start < TWIN_CALIBRATION_NS) {
        twin_cycle();
        TWIN_BARRIER();
        calls++;
    }
    double once_ns = (twin_now_ns() - start) / (double)calls;
    uint64_t repetitions = (uint64_t)(TWIN_BATCH_NS / once_ns);
    if (repetitions < 1) {
        repetitions = 1;
    }

    double times_ns[TWIN_BATCHES];
    for (int batch = 0; batch < TWIN_BATCHES; batch++) {
        double batch_start = twin_now_ns();
        for (uint64_t repetition = 0; repetition < repetitions; repetition++) {
            twin_cycle();
            TWIN_BARRIER();
        }
        times_ns[batch] = (twin_now_ns() - batch_start) / (double)repetitions;
    }
    qsort(times_ns, TWIN_BATCHES, sizeof times_ns[0], twin_compare);
    printf("{\"ns_per_cycle\": %.3f, \"check\": %lld}\n", times_ns[TWIN_BATCHES / 2], check);
    return 0;
}

#endif
