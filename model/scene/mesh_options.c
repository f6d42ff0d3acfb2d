// SPDX-License-Identifier: Apache-2.0
/* mesh_options.c: the "mesh FILE [options]" directive's options (mesh_options.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "mesh_options.h"

static int number(const char *s, double *v)
{
    char *end;
    *v = strtod(s, &end);
    return end != s && *end == '\0' && isfinite(*v);
}

/* Apply the linear map a (3x3) after the current transform. */
static void compose(mesh_opts_t *o, const double a[3][3])
{
    double m[3][3];
    double t[3] = {o->t.x, o->t.y, o->t.z}, nt[3];
    for (int i = 0; i < 3; i++) {
        nt[i] = a[i][0] * t[0] + a[i][1] * t[1] + a[i][2] * t[2];
        for (int j = 0; j < 3; j++) m[i][j] = a[i][0] * o->m[0][j] + a[i][1] * o->m[1][j] + a[i][2] * o->m[2][j];
    }
    memcpy(o->m, m, sizeof m);
    o->t = v3(nt[0], nt[1], nt[2]);
}

int mesh_parse_options(const scene_t *s, const char *scene_file, char **tok, int ntok, mesh_opts_t *o,
                       char *err, size_t errlen)
{
    memset(o, 0, sizeof *o);
    o->material = -1;
    o->m[0][0] = o->m[1][1] = o->m[2][2] = 1;
    o->emission = 1;
    const char *slash = strrchr(scene_file, '/');
    if (tok[0][0] == '/' || !slash) snprintf(o->path, sizeof o->path, "%s", tok[0]);
    else snprintf(o->path, sizeof o->path, "%.*s/%s", (int)(slash - scene_file), scene_file, tok[0]);
    for (int i = 1; i < ntok;) {
        const char *k = tok[i];
        double v[3];
        if (!strcmp(k, "material") && i + 1 < ntok) {
            o->material = scene_find_material(s, tok[i + 1]);
            if (o->material < 0) { snprintf(err, errlen, "mesh: unknown material '%s' (define it first)", tok[i + 1]); return -1; }
            i += 2;
        } else if ((!strcmp(k, "map") && i + 2 < ntok) || (!strcmp(k, "exclude") && i + 1 < ntok)) {
            if (o->nmap == MAX_MAPS) { snprintf(err, errlen, "mesh: more than %d map/exclude options", MAX_MAPS); return -1; }
            if (strlen(tok[i + 1]) >= sizeof o->map_name[0]) { snprintf(err, errlen, "mesh: name '%s' is too long", tok[i + 1]); return -1; }
            strcpy(o->map_name[o->nmap], tok[i + 1]);
            if (k[0] == 'm') {
                o->map_mat[o->nmap] = scene_find_material(s, tok[i + 2]);
                if (o->map_mat[o->nmap] < 0) { snprintf(err, errlen, "mesh: unknown material '%s' (define it first)", tok[i + 2]); return -1; }
                i += 3;
            } else {
                o->map_mat[o->nmap] = -2;
                i += 2;
            }
            o->nmap++;
        } else if (!strcmp(k, "scale") && i + 1 < ntok) {
            if (!number(tok[i + 1], &v[0])) { snprintf(err, errlen, "mesh: scale: expected a number, found '%s'", tok[i + 1]); return -1; }
            int three = i + 3 < ntok && number(tok[i + 2], &v[1]) && number(tok[i + 3], &v[2]);
            if (!three) v[1] = v[2] = v[0];
            if (v[0] == 0 || v[1] == 0 || v[2] == 0) { snprintf(err, errlen, "mesh: scale must not be zero"); return -1; }
            double a[3][3] = {{v[0], 0, 0}, {0, v[1], 0}, {0, 0, v[2]}};
            compose(o, a);
            i += three ? 4 : 2;
        } else if (!strcmp(k, "translate") && i + 3 < ntok) {
            for (int j = 0; j < 3; j++)
                if (!number(tok[i + 1 + j], &v[j])) { snprintf(err, errlen, "mesh: translate: expected a number, found '%s'", tok[i + 1 + j]); return -1; }
            o->t = v3_add(o->t, v3(v[0], v[1], v[2]));
            i += 4;
        } else if (!strcmp(k, "rotate") && i + 2 < ntok) {
            const char *ax = tok[i + 1];
            if (strlen(ax) != 1 || !strchr("xyz", ax[0])) { snprintf(err, errlen, "mesh: rotate: axis must be x, y or z, found '%s'", ax); return -1; }
            if (!number(tok[i + 2], &v[0])) { snprintf(err, errlen, "mesh: rotate: expected degrees, found '%s'", tok[i + 2]); return -1; }
            double r = v[0] * PREE_PI / 180.0, c = cos(r), sn = sin(r);
            int p = ax[0] == 'x' ? 1 : ax[0] == 'y' ? 2 : 0, q = (p + 1) % 3;  /* rotates p toward q */
            double a[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
            a[p][p] = c; a[p][q] = -sn; a[q][p] = sn; a[q][q] = c;
            compose(o, a);
            i += 3;
        } else if (!strcmp(k, "normals") && i + 1 < ntok) {
            const char *m = tok[i + 1];
            if (!strcmp(m, "file")) o->normals = NORMALS_FILE;
            else if (!strcmp(m, "flat")) o->normals = NORMALS_FLAT;
            else if (!strcmp(m, "smooth")) o->normals = NORMALS_SMOOTH;
            else { snprintf(err, errlen, "mesh: normals must be file, flat or smooth, found '%s'", m); return -1; }
            i += 2;
        } else if (!strcmp(k, "emission") && i + 1 < ntok) {
            if (!number(tok[i + 1], &o->emission) || o->emission < 0) { snprintf(err, errlen, "mesh: emission needs a number >= 0, found '%s'", tok[i + 1]); return -1; }
            i += 2;
        } else {
            snprintf(err, errlen, "mesh: unexpected '%s' (or too few values after it)", k);
            return -1;
        }
    }
    return 0;
}
