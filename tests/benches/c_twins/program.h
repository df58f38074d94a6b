/*
 * The instance of the `main` program shared by the bool, dint, real and array_loop workloads
 * (DECLARATIONS in tests/benches/workloads/mod.rs), member for member, with its initial
 * values, and the wrapping arithmetic of ST's DINT.
 */
#ifndef RIVET_TWIN_PROGRAM_H
#define RIVET_TWIN_PROGRAM_H

#include <stdbool.h>
#include <stdint.h>

struct main_program {
    bool b1, b2, b3, b4, b5;
    int32_t i1, i2, i3;
    float r1, r2, r3;
    int32_t i;
    int32_t a[1000];
};

static struct main_program m = {
    .b1 = true,
    .i1 = 1,
    .i2 = 2,
    .r1 = 1.0f,
    .r2 = 2.0f,
};

/* DINT addition and subtraction wrap, as in ST; signed overflow in C would not. */
static inline int32_t dint_add(int32_t a, int32_t b)
{
    return (int32_t)((uint32_t)a + (uint32_t)b);
}

static inline int32_t dint_sub(int32_t a, int32_t b)
{
    return (int32_t)((uint32_t)a - (uint32_t)b);
}

#endif
