// SPDX-License-Identifier: Apache-2.0
/* atomic_out.h: every output file (images, statistics) is written to a temporary beside its
 * target and renamed over it only when complete, and only over a regular file (or nothing):
 * a device (/dev/null), a directory or a symbolic link at the target is refused, never
 * replaced. The temporary's name, "<dir>/.pree.tmp-<pid>-<n>", does not grow with the target's
 * name, so any name the file system takes works. Live temporaries are listed and removed on
 * exit() (atexit) and by atomic_out_cleanup(), which a fatal-signal handler may call. */
#ifndef PREE_ATOMIC_OUT_H
#define PREE_ATOMIC_OUT_H

#include <stddef.h>

/* 0 when path may be replaced: absent or a regular file; else -1 with "PATH: why" in err. */
int atomic_out_target_ok(const char *path, char *err, size_t errlen);
/* Create the temporary for path (exclusively, mode 0666 less the umask) and list it. Returns
 * the open descriptor and fills tmp (tmplen >= 4096), or -1 with "PATH: why" in err. */
int atomic_out_begin(const char *path, char *tmp, size_t tmplen, char *err, size_t errlen);
/* Rename the finished temporary over path (after atomic_out_target_ok) and unlist it; on
 * failure remove it. 0, or -1 with "PATH: why" in err. */
int atomic_out_commit(const char *tmp, const char *path, char *err, size_t errlen);
/* Remove an unfinished temporary and unlist it. */
void atomic_out_discard(const char *tmp);
/* Remove every listed temporary (async-signal-safe: unlink only). */
void atomic_out_cleanup(void);

#endif
