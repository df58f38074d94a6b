/*
 * The C twin of the `fb_calls` workload: 1,000 calls of the function block Accumulate on four
 * instances, each call setting the two inputs and reading the output, as FB_CALL_STATEMENTS.
 */
#include <stdint.h>

/* An instance of FUNCTION_BLOCK Accumulate: inputs in1, in2, output q, state lim. */
struct accumulate {
    int32_t in1, in2;
    int32_t q;
    int32_t lim;
};

/* The instance of the fb_calls `main` program, member for member. */
struct main_program {
    struct accumulate f1, f2, f3, f4;
    int32_t i1, i2, i3;
};

static struct main_program m = {
    .f1 = {.lim = 1000000},
    .f2 = {.lim = 1000000},
    .f3 = {.lim = 1000000},
    .f4 = {.lim = 1000000},
    .i1 = 1,
    .i2 = 2,
};

/* q := q + in1 * in2; IF q > lim THEN q := 0; END_IF, with DINT's wrapping arithmetic.
 * gcc -O2 inlines this call and keeps the four instances in registers across the rounds, as it
 * may: the C column is what an optimising C compiler makes of the program, not the cost of a
 * call, so the ratio against it measures calls against no calls at all (docs/native-engine.md
 * §11.3 reports it, but sets no goal for it). */
static void accumulate(struct accumulate *block)
{
    block->q = (int32_t)((uint32_t)block->q + (uint32_t)block->in1 * (uint32_t)block->in2);
    if (block->q > block->lim) {
        block->q = 0;
    }
}

static void twin_cycle(void)
{
    for (int round = 0; round < 250; round++) {
        m.f1.in1 = m.i1;
        m.f1.in2 = 3;
        accumulate(&m.f1);
        m.i2 = m.f1.q;
        m.f2.in1 = m.i2;
        m.f2.in2 = 5;
        accumulate(&m.f2);
        m.i3 = m.f2.q;
        m.f3.in1 = m.i3;
        m.f3.in2 = -7;
        accumulate(&m.f3);
        m.i1 = m.f3.q;
        m.f4.in1 = m.i1;
        m.f4.in2 = m.i2;
        accumulate(&m.f4);
        m.i3 = m.f4.q;
    }
}

static long long twin_check(void)
{
    return m.i3;
}

#include "timing.h"
