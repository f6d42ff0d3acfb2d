// SPDX-License-Identifier: Apache-2.0
/* text_escape.h: text from files (scene tokens, mesh names) made safe to print on a terminal:
 * control bytes (C0, DEL, and C1 as UTF-8), invisible marks (a byte-order mark, zero-width and
 * bidirectional controls) and bytes that are not UTF-8 become \xNN (byte by byte), so that
 * no escape sequence or binary byte from an input reaches the terminal raw. */
#ifndef PREE_TEXT_ESCAPE_H
#define PREE_TEXT_ESCAPE_H

#include <stdarg.h>
#include <stddef.h>

/* Copy src to dst (cap bytes, always terminated when cap > 0), escaping as above; a sequence
 * that does not fit whole is dropped. Returns dst. */
char *text_escape(const char *src, char *dst, size_t cap);

/* An error message "FILE:LINE: message" (line 0: "FILE: message") into err[errlen], the message
 * formatted from fmt and ap and escaped as above. */
void text_error_at(char *err, size_t errlen, const char *file, int line, const char *fmt, va_list ap);

#endif
