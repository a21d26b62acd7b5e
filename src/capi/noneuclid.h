/* noneuclid.h: the C interface to the noneuclid engine (docs/library.md).
 *
 * A world of constant curvature K in [-1, 1], made from a scene (a TOML scene file's text or a
 * built-in scene's name), stepped 1/60 s at a time, driven by the same controls as the program's
 * buttons, drawn into the caller's pixel buffer, and read back: its bodies and the game's events.
 *
 *     nw_world* w = NULL;
 *     if (nw_world_from_name("kiosk", NULL, &w) != NW_OK) { puts(nw_last_error()); return 1; }
 *     nw_step(w, 60);
 *     nw_draw(w, pixels, sizeof pixels, 320, 240, 0, "xrgb8888");
 *     nw_world_free(w);
 *
 * Errors: every function that can fail returns an nw_status; NW_OK is 0. On a failure,
 * nw_last_error() gives one sentence naming what was wrong and how to fix it, for the calling
 * thread, until its next failure. No call aborts on bad input: a null pointer, a bad scene, a
 * bad name or a buffer too small is a status and a sentence.
 *
 * Threads: a world is used by one thread at a time; different worlds on different threads.
 * Memory: making a world allocates; stepping, drawing and reading it do not (the first draw
 * into a canvas of a new size may). nw_version's string lives as long as the program,
 * nw_last_error's until the calling thread's next failure; bodies' names are copied out.
 *
 * Versions follow semantic versioning of this interface: the same major version keeps every
 * declaration here and its meaning; a minor version adds. While the major version is 0, a
 * minor version may change the interface too, and says so in docs/library.md.
 */
#ifndef NONEUCLID_H
#define NONEUCLID_H

#include <stddef.h>

#define NW_VERSION_MAJOR 0
#define NW_VERSION_MINOR 1
#define NW_VERSION_PATCH 0
/* MAJOR * 10000 + MINOR * 100 + PATCH: compare with nw_version_number() at run time. */
#define NW_VERSION_NUMBER (NW_VERSION_MAJOR * 10000 + NW_VERSION_MINOR * 100 + NW_VERSION_PATCH)

#if defined(_WIN32)
#define NW_API
#elif defined(__GNUC__)
#define NW_API __attribute__((visibility("default")))
#else
#define NW_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

typedef enum nw_status {
    NW_OK = 0,
    NW_ERR_NULL = 1,     /* a pointer that must not be null was */
    NW_ERR_SCENE = 2,    /* the scene text or name is not a scene the engine can run */
    NW_ERR_NAME = 3,     /* an unknown name: engine, control, pixel format, projection */
    NW_ERR_SIZE = 4,     /* a size out of range, or a buffer too small for it */
    NW_ERR_RANGE = 5,    /* a number out of its range (K, steps, an index) */
    NW_ERR_MEMORY = 6,   /* out of memory */
    NW_ERR_INTERNAL = 7  /* a bug: please report it with nw_last_error()'s sentence */
} nw_status;

typedef struct nw_world nw_world;

/* The library's version, "MAJOR.MINOR.PATCH", and as NW_VERSION_NUMBER counts it. */
NW_API const char* nw_version(void);
NW_API int nw_version_number(void);
/* The calling thread's last failure, one sentence; "" if none. */
NW_API const char* nw_last_error(void);

/* A world from a TOML scene file's text (docs/file-formats.md, "Scene files"), `length` bytes
 * (it need not end with a NUL). `engine`: "fixed" (fixed point and lookup tables, the device's;
 * also for NULL) or "double" (the same forms in double, the reference). Textures may name the
 * built-in images only ("builtin:..."). */
NW_API nw_status nw_world_from_text(const char* text, size_t length, const char* engine, nw_world** out);
/* A world from a built-in scene: kiosk, asteroids, textured, measure, fig1, ..., earth, stress
 * (`noneuclid scenes` lists them). */
NW_API nw_status nw_world_from_name(const char* name, const char* engine, nw_world** out);
/* Frees a world; NULL is allowed. */
NW_API void nw_world_free(nw_world* w);

/* `steps` steps of 1/60 s world time, 0 to 1000000 per call. */
NW_API nw_status nw_step(nw_world* w, long steps);
/* `seconds` of time (a frame's, 0 to 16666) in whole steps of 1/60 s: the part short of a step
 * is kept and added to the next call's, so that a loop with uneven frame times moves the world
 * in the same equal steps as nw_step. The steps taken into *steps if not NULL. */
NW_API nw_status nw_advance(nw_world* w, double seconds, long* steps);
/* World seconds and steps so far. */
NW_API nw_status nw_clock(const nw_world* w, double* seconds, long* steps);

/* K now; setting it keeps every body's polar numbers (the paper's rule). K in [-1, 1]. */
NW_API nw_status nw_curvature(const nw_world* w, double* K);
NW_API nw_status nw_set_curvature(nw_world* w, double K);

/* A control pressed (pressed != 0) or released, at once (the world's state changes now; the
 * next nw_step sees it): "thrust", "left", "right", "curvature_up", "curvature_down" and "fire"
 * act while held, over the steps that follow; "preset", "reset", "hyperbolic", "flat",
 * "spherical" and "instrument" act on the press. */
NW_API nw_status nw_control(nw_world* w, const char* control, int pressed);

/* How nw_draw projects: "equidistant" (the default), "stereographic", "gnomonic",
 * "orthographic" or "lambert"; antialiased lines or not (the default). */
NW_API nw_status nw_set_view(nw_world* w, const char* projection, int antialias);

/* Draws the world into `pixels`, `capacity` bytes: width x height pixels (each 1 to 8192),
 * rows `stride` bytes apart (0: width times the format's bytes per pixel), in the pixel format
 * named: "xrgb8888", "rgb565", "rgb888" (`noneuclid render --format`), "bgr565", "xbgr8888",
 * "bgr888" or "rgba8888". Pixels are little-endian words (rgb888: bytes B, G, R). The same
 * scene, steps and controls give `noneuclid render`'s pixels (without its HUD). */
NW_API nw_status nw_draw(nw_world* w, void* pixels, size_t capacity, int width, int height, ptrdiff_t stride,
                         const char* format);
/* The bytes a pixel takes in the format named (2, 3 or 4). */
NW_API nw_status nw_format_bytes(const char* format, int* bytes);

typedef struct nw_body {
    char name[64];      /* the scene's name, or "asteroid 12" for a game's; cut to 63 bytes */
    char kind[16];      /* "ship", "asteroid", "bullet", "grid", "instrument" or "body" */
    double r;           /* the centre's distance from O, world units */
    double theta;       /* the centre's angle, degrees in (-180, 180] */
    double facing;      /* degrees in (-180, 180], in the frame carried from O */
    double speed;       /* world units per second */
    double travel;      /* the direction of travel, degrees, like facing */
    int vertices;       /* of its outline */
} nw_body;

/* The bodies in the world now (a game's spare slots left out), as `noneuclid dump` lists them,
 * in the same order. */
NW_API nw_status nw_body_count(const nw_world* w, int* count);
NW_API nw_status nw_body_at(const nw_world* w, int index, nw_body* out);

typedef enum nw_event_kind {
    NW_EVENT_START = 0,  /* a game began */
    NW_EVENT_HIT = 1,    /* bullet `bullet` hit asteroid `asteroid` */
    NW_EVENT_CRASH = 2,  /* the ship hit asteroid `asteroid` */
    NW_EVENT_LEVEL = 3,  /* level `value` began */
    NW_EVENT_OVER = 4    /* the game ended with the score `value` */
} nw_event_kind;

typedef struct nw_event {
    int kind;            /* an nw_event_kind */
    long value;
    unsigned long bullet, asteroid;  /* their numbers: "bullet 3", "asteroid 12" */
} nw_event;

typedef struct nw_game {
    int on;              /* the scene has the game */
    int phase;           /* 0 ready ("press fire"), 1 playing, 2 over */
    long score;
    int lives, level;
} nw_game;

/* The game now, and what happened in the last step: nw_event_count events, each by index. */
NW_API nw_status nw_game_state(const nw_world* w, nw_game* out);
NW_API nw_status nw_event_count(const nw_world* w, int* count);
NW_API nw_status nw_event_at(const nw_world* w, int index, nw_event* out);

#ifdef __cplusplus
}
#endif

#endif /* NONEUCLID_H */
