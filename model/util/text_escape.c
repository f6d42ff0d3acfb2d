// SPDX-License-Identifier: Apache-2.0
/* text_escape.c: escape control and non-UTF-8 bytes for the terminal (text_escape.h). */
#include <stdio.h>
#include <string.h>
#include "text_escape.h"

/* The length of the valid UTF-8 sequence at s that encodes a visible code point (not the C1
 * controls U+0080..U+009F, a byte-order mark, zero-width or bidirectional controls), or 0. Overlong forms and surrogates are not valid. */
static size_t utf8_printable(const unsigned char *s)
{
    unsigned c = s[0];
    size_t n = c >= 0xF0 && c <= 0xF4 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 && c < 0xE0 ? 2 : 0;
    if (n == 0) return 0;
    unsigned cp = c & (0x7F >> n);
    for (size_t k = 1; k < n; k++) {
        if ((s[k] & 0xC0) != 0x80) return 0;
        cp = cp << 6 | (s[k] & 0x3F);
    }
    if ((n == 3 && (cp < 0x800 || (cp >= 0xD800 && cp <= 0xDFFF))) || (n == 4 && (cp < 0x10000 || cp > 0x10FFFF)))
        return 0;
    int invisible = (cp >= 0x80 && cp <= 0x9F) || cp == 0xFEFF || (cp >= 0x200B && cp <= 0x200F) ||
                    (cp >= 0x202A && cp <= 0x202E) || (cp >= 0x2066 && cp <= 0x2069);
    return invisible ? 0 : n;
}

char *text_escape(const char *src, char *dst, size_t cap)
{
    const unsigned char *s = (const unsigned char *)src;
    size_t o = 0;
    if (cap == 0) return dst;
    while (*s) {
        size_t n = *s >= 0x20 && *s < 0x7F ? 1 : *s >= 0x80 ? utf8_printable(s) : 0;
        if (n == 0) {   /* a byte to escape */
            if (o + 4 >= cap) break;
            snprintf(dst + o, 5, "\\x%02X", *s);
            o += 4;
            s++;
            continue;
        }
        if (o + n >= cap) break;
        memcpy(dst + o, s, n);
        o += n;
        s += n;
    }
    dst[o] = '\0';
    return dst;
}

void text_error_at(char *err, size_t errlen, const char *file, int line, const char *fmt, va_list ap)
{
    char msg[1024], safe[sizeof msg * 4];
    vsnprintf(msg, sizeof msg, fmt, ap);
    text_escape(msg, safe, sizeof safe);   /* an input's bytes never reach the terminal raw */
    if (line) snprintf(err, errlen, "%s:%d: %s", file, line, safe);
    else snprintf(err, errlen, "%s: %s", file, safe);
}
