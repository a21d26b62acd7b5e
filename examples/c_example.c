/* The C interface (noneuclid.h, docs/library.md): a world from a scene file's text or a built-in
 * scene's name, run for some frames, drawn into a buffer in the pixel format named, written as
 * a PPM file, and its bodies printed. tests/library compares the picture with
 * `noneuclid render --format FORMAT` of the same scene, pixel for pixel.
 *
 *   example_c SCENE FRAMES WIDTHxHEIGHT FORMAT OUT.ppm    SCENE: a built-in name or a .toml file
 */
#include <noneuclid.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The whole file, or NULL. */
static char* read_file(const char* path, size_t* length) {
    FILE* f = fopen(path, "rb");
    char* text = NULL;
    long size;
    if (!f) return NULL;
    if (fseek(f, 0, SEEK_END) == 0 && (size = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0 &&
        (text = malloc((size_t)size + 1)) != NULL) {
        *length = fread(text, 1, (size_t)size, f);
    }
    fclose(f);
    return text;
}

/* Pixel (x, y) of a little-endian buffer as 8-bit R, G, B: rgb565's 5 and 6 bits widened as the
 * renderer does (the top bits repeated below), xrgb8888's bytes as they are. */
static void rgb_at(const unsigned char* p, int bytes, unsigned char out[3]) {
    if (bytes == 2) {
        unsigned w = (unsigned)p[0] | (unsigned)p[1] << 8, r = w >> 11, g = (w >> 5) & 63, b = w & 31;
        out[0] = (unsigned char)(r << 3 | r >> 2), out[1] = (unsigned char)(g << 2 | g >> 4);
        out[2] = (unsigned char)(b << 3 | b >> 2);
    } else {
        out[0] = p[2], out[1] = p[1], out[2] = p[0];
    }
}

int main(int argc, char** argv) {
    nw_world* w = NULL;
    int width = 0, height = 0, bytes = 0, count = 0, i;
    nw_status s;
    if (argc != 6 || sscanf(argv[3], "%dx%d", &width, &height) != 2) {
        fprintf(stderr, "usage: example_c SCENE FRAMES WIDTHxHEIGHT FORMAT OUT.ppm\n");
        return 2;
    }
    printf("noneuclid %s (built against %d)\n", nw_version(), NW_VERSION_NUMBER);
    if (strstr(argv[1], ".toml")) {
        size_t length = 0;
        char* text = read_file(argv[1], &length);
        if (!text) {
            perror(argv[1]);
            return 1;
        }
        s = nw_world_from_text(text, length, "fixed", &w);
        free(text);
    } else {
        s = nw_world_from_name(argv[1], NULL, &w);
    }
    if (s == NW_OK) s = nw_step(w, atol(argv[2]));
    if (s == NW_OK) s = nw_format_bytes(argv[4], &bytes);
    if (s != NW_OK) {
        fprintf(stderr, "example_c: %s\n", nw_last_error());
        nw_world_free(w);
        return 1;
    }
    {
        size_t size = (size_t)width * (size_t)height * (size_t)bytes;
        unsigned char* pixels = malloc(size ? size : 1);
        FILE* out = fopen(argv[5], "wb");
        s = pixels && out ? nw_draw(w, pixels, size, width, height, 0, argv[4]) : NW_ERR_MEMORY;
        if (s == NW_OK) {
            fprintf(out, "P6\n%d %d\n255\n", width, height);
            for (i = 0; i < width * height; ++i) {
                unsigned char rgb[3];
                rgb_at(pixels + (size_t)i * (size_t)bytes, bytes, rgb);
                fwrite(rgb, 1, 3, out);
            }
        } else {
            fprintf(stderr, "example_c: %s\n", s == NW_ERR_MEMORY ? "no memory or no output file" : nw_last_error());
        }
        if (out && fclose(out) != 0) s = NW_ERR_INTERNAL;
        free(pixels);
    }
    nw_body_count(w, &count);
    for (i = 0; i < count; ++i) {
        nw_body b;
        nw_body_at(w, i, &b);
        printf("%s (%s): r %.4f, theta %.2f, facing %.2f\n", b.name, b.kind, b.r, b.theta, b.facing);
    }
    nw_world_free(w);
    return s == NW_OK ? 0 : 1;
}
