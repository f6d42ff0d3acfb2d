// SPDX-License-Identifier: Apache-2.0
/* file_in.c: open an input only when it is a regular file of bounded size (file_in.h). */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "file_in.h"

FILE *file_in_open(const char *path, long long max_bytes, char *err, size_t errlen)
{
    /* O_NONBLOCK: opening a FIFO with no writer would otherwise wait for ever. */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) { snprintf(err, errlen, "%s: %s", path, strerror(errno)); return NULL; }
    struct stat st;
    const char *why = NULL;
    int big = 0;
    if (fstat(fd, &st) != 0) why = strerror(errno);
    else if (S_ISDIR(st.st_mode)) why = "is a directory, not a file";
    else if (!S_ISREG(st.st_mode)) why = "not a regular file (a device, FIFO or socket cannot be read)";
    else if (st.st_size > max_bytes) big = 1;
    if (why || big) {
        if (big)
            snprintf(err, errlen, "%s: %lld bytes is more than the input limit of %lld bytes", path,
                     (long long)st.st_size, max_bytes);
        else
            snprintf(err, errlen, "%s: %s", path, why);
        close(fd);
        return NULL;
    }
    int fl = fcntl(fd, F_GETFL);
    FILE *f = fl < 0 || fcntl(fd, F_SETFL, fl & ~O_NONBLOCK) < 0 ? NULL : fdopen(fd, "rb");
    if (!f) { snprintf(err, errlen, "%s: %s", path, strerror(errno)); close(fd); }
    return f;
}
