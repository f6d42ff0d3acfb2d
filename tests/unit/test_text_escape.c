// SPDX-License-Identifier: Apache-2.0
/* test_text_escape.c: terminal escaping of file text (model/util/text_escape.c): printable
 * ASCII and visible UTF-8 pass; control bytes, C1, byte-order marks, bidirectional controls
 * and bytes that are not UTF-8 become \xNN; the output always fits and is terminated. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <string.h>
#include "text_escape.h"

static void expect(const char *in, const char *want)
{
    char out[256];
    assert_string_equal(text_escape(in, out, sizeof out), want);
}

static void test_escapes(void **state)
{
    (void)state;
    expect("sphere 1 0 0 -5 m", "sphere 1 0 0 -5 m");
    expect("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80", "caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80");   /* e-acute, euro, emoji */
    expect("a\x1B[31mb\x7F", "a\\x1B[31mb\\x7F");
    expect("\t\r\n", "\\x09\\x0D\\x0A");
    expect("\xC2\x9B" "x", "\\xC2\\x9Bx");                     /* C1 CSI as UTF-8 */
    expect("\xEF\xBB\xBF" "camera", "\\xEF\\xBB\\xBFcamera");  /* byte-order mark */
    expect("\xE2\x80\xAE" "abc", "\\xE2\\x80\\xAEabc");        /* right-to-left override */
    expect("\xC0\xAF \xED\xA0\x80 \xFF", "\\xC0\\xAF \\xED\\xA0\\x80 \\xFF");   /* overlong, surrogate, invalid */
    expect("\xE2\x82", "\\xE2\\x82");                          /* truncated sequence */
}

static void test_fits(void **state)
{
    (void)state;
    char out[6];
    assert_string_equal(text_escape("abcdefgh", out, sizeof out), "abcde");
    assert_string_equal(text_escape("ab\x01" "cd", out, sizeof out), "ab");   /* \x01 needs 4 */
    assert_string_equal(text_escape("a\xC3\xA9\xC3\xA9", out, sizeof out), "a\xC3\xA9\xC3\xA9");
    char one[1] = {'z'};
    assert_string_equal(text_escape("abc", one, sizeof one), "");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_escapes),
        cmocka_unit_test(test_fits),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
