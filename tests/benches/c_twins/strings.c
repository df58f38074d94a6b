/*
 * The C twin of the `strings` workload: 100 rounds of
 *   s := CONCAT(LEFT(t, 5), DINT_TO_STRING(n)); n := n + FIND(s, '1');
 * on STRING(80) variables, each function cutting its result to 80 characters as ST does.
 */
#include <inttypes.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

/* The characters a STRING(80) holds; its storage has one more byte for the terminator. */
#define CAPACITY 80

/* The instance of the strings `main` program, member for member. */
struct main_program {
    char s[CAPACITY + 1];
    char t[CAPACITY + 1];
    int32_t n;
};

static struct main_program m = {
    .t = "Cell1 packaging line",
};

/* LEFT(source, count) into a STRING(80). */
static void left(char *target, const char *source, int32_t count)
{
    size_t length = strlen(source);
    size_t taken = count < 0 ? 0 : (size_t)count;
    if (taken > length) {
        taken = length;
    }
    if (taken > CAPACITY) {
        taken = CAPACITY;
    }
    memcpy(target, source, taken);
    target[taken] = '\0';
}

/* CONCAT(a, b) into a STRING(80): what does not fit is cut off. */
static void concat(char *target, const char *a, const char *b)
{
    size_t a_length = strlen(a);
    size_t b_length = strlen(b);
    if (a_length > CAPACITY) {
        a_length = CAPACITY;
    }
    if (b_length > CAPACITY - a_length) {
        b_length = CAPACITY - a_length;
    }
    memmove(target, a, a_length);
    memmove(target + a_length, b, b_length);
    target[a_length + b_length] = '\0';
}

/* FIND(haystack, needle): the 1-based position of the first occurrence, 0 when there is none. */
static int16_t find(const char *haystack, const char *needle)
{
    const char *found = strstr(haystack, needle);
    return found == NULL ? 0 : (int16_t)(found - haystack + 1);
}

static void twin_cycle(void)
{
    for (int round = 0; round < 100; round++) {
        char head[CAPACITY + 1];
        char number[CAPACITY + 1];
        left(head, m.t, 5);
        snprintf(number, sizeof number, "%" PRId32, m.n);
        concat(m.s, head, number);
        m.n = (int32_t)((uint32_t)m.n + (uint32_t)(int32_t)find(m.s, "1"));
    }
}

static long long twin_check(void)
{
    return m.n;
}

#include "timing.h"
