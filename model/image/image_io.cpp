// SPDX-License-Identifier: Apache-2.0
// image_io.cpp: the project's only C++: OpenImageIO 2.4 behind the extern "C" API of image_io.h.
// Every bool OpenImageIO returns is checked; its (possibly multi-line) error text is folded into
// one line after the file name. No exception crosses into C.
#include "image_io.h"

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using OIIO::ImageInput;
using OIIO::ImageOutput;
using OIIO::ImageSpec;
using OIIO::TypeDesc;

// Put "path: what: why" into err as one line (newlines in OIIO's messages become "; ").
static int fail(char *err, size_t errlen, const char *path, const char *what, std::string why)
{
    if (why.empty()) why = OIIO::geterror();   // some readers report only globally
    if (err && errlen) {
        while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();
        for (size_t i = 0; i < why.size(); i++)
            if (why[i] == '\n') why.replace(i, 1, "; ");
        if (why.empty()) why = "truncated or malformed (OpenImageIO gave no reason)";
        std::snprintf(err, errlen, "%s: %s: %s", path, what, why.c_str());
    }
    return -1;
}

extern "C" int pree_oiio_write(const char *path, const char *format, int w, int h, int is_float,
                               const void *pixels, const char *const *meta, char *err, size_t errlen)
{
    try {
        // Create the writer by format name, so the (temporary) file name needs no extension.
        auto out = ImageOutput::create(format);
        if (!out) return fail(err, errlen, path, "no image writer", OIIO::geterror());
        const TypeDesc type = is_float ? TypeDesc::FLOAT : TypeDesc::UINT8;
        ImageSpec spec(w, h, 3, type);
        // No time stamp (OpenImageIO stamps EXR files with the time otherwise): identical pixels
        // give identical files.
        spec.attribute("DateTime", "");
        for (size_t k = 0; meta && meta[k]; k += 2) spec.attribute(meta[k], meta[k + 1] ? meta[k + 1] : "");
        if (!out->open(path, spec))
            return fail(err, errlen, path, "cannot open for writing", out->geterror());
        if (!out->write_image(type, pixels)) {
            std::string why = out->geterror();
            (void)out->close();
            return fail(err, errlen, path, "write failed", why);
        }
        if (!out->close()) return fail(err, errlen, path, "close failed", out->geterror());
        return 0;
    } catch (const std::exception &e) {
        return fail(err, errlen, path, "write failed", e.what());
    }
}

// Copy n pixels of nc channels (1 or 3) into RGB floats; one channel is replicated.
template <typename T>
static void to_rgb(const T *src, int nc, size_t n, float *dst)
{
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) dst[3 * i + c] = (float)src[i * nc + (nc == 3 ? c : 0)];
}

extern "C" int pree_oiio_read(const char *path, pree_image_t *img, char *err, size_t errlen)
{
    img->width = img->height = 0;
    img->rgb = nullptr;
    img->samples = PREE_SAMPLES_FLOAT;
    try {
        auto in = ImageInput::open(path);
        if (!in) return fail(err, errlen, path, "cannot read image", OIIO::geterror());
        const ImageSpec &spec = in->spec();
        if (spec.width < 1 || spec.height < 1 || spec.depth != 1 || spec.nchannels < 1)
            return fail(err, errlen, path, "unsupported image", "empty or volume image");
        if ((int64_t)spec.width * spec.height > ((int64_t)1 << 28))
            return fail(err, errlen, path, "unsupported image", "more than 2^28 pixels");
        const int nc = spec.nchannels >= 3 ? 3 : 1;   // RGB, or grey replicated
        const size_t n = (size_t)spec.width * spec.height;

        // Integer files keep their integer values; everything else reads as float.
        TypeDesc type = TypeDesc::FLOAT;
        int samples = PREE_SAMPLES_FLOAT;
        if (spec.format.basetype == TypeDesc::UINT8) { type = TypeDesc::UINT8; samples = PREE_SAMPLES_U8; }
        if (spec.format.basetype == TypeDesc::UINT16) { type = TypeDesc::UINT16; samples = PREE_SAMPLES_U16; }

        std::vector<unsigned char> raw(n * nc * type.size());
        if (!in->read_image(0, 0, 0, nc, type, raw.data()))
            return fail(err, errlen, path, "read failed", in->geterror());
        if (!in->close()) return fail(err, errlen, path, "close failed", in->geterror());

        float *rgb = (float *)std::malloc(n * 3 * sizeof(float));
        if (!rgb) return fail(err, errlen, path, "read failed", "out of memory");
        if (samples == PREE_SAMPLES_U8) to_rgb((const uint8_t *)raw.data(), nc, n, rgb);
        else if (samples == PREE_SAMPLES_U16) to_rgb((const uint16_t *)raw.data(), nc, n, rgb);
        else to_rgb((const float *)raw.data(), nc, n, rgb);
        img->width = spec.width;
        img->height = spec.height;
        img->rgb = rgb;
        img->samples = samples;
        return 0;
    } catch (const std::exception &e) {
        return fail(err, errlen, path, "read failed", e.what());
    }
}
