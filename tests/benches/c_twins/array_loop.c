/* The C twin of the `array_loop` workload: FOR i := 1 TO 1000 DO a[i] := a[i] + i; END_FOR. */
#include "program.h"

static void twin_cycle(void)
{
    /* The loop variable is the instance's `i`, which ends at 1001 as in ST. */
    for (m.i = 1; m.i <= 1000; m.i++) {
        m.a[m.i - 1] = dint_add(m.a[m.i - 1], m.i);
    }
}

static long long twin_check(void)
{
    return m.a[999];
}

#include "timing.h"
