/* SPDX-License-Identifier: Apache-2.0 */
/*
 * pn_plugins_describe from C99, as an app or a listing tool calls it: over the
 * two directories of lazy fixtures (ten libraries, each leaving the mark
 * PEDNAV_TEST_OPENED_<name> when opened).
 *
 *   plugins_describe_test LAZY_A_DIR LAZY_B_DIR
 *
 * flags 0 lists all 30 plugins from the manifests and opens nothing;
 * PN_LIST_OPEN_LIBRARIES opens (and closes again) all ten; the two-call size
 * idiom, unknown flags and NULL directories are refused with a reason.
 */
#define _POSIX_C_SOURCE 200112L /* unsetenv */
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <pednav/pn_engine.h>

static int failures = 0;

#define EXPECT(cond)                                                    \
    do {                                                                \
        if (!(cond)) {                                                  \
            fprintf(stderr, "%s:%d: expected %s\n", __FILE__, __LINE__, #cond); \
            ++failures;                                                 \
        }                                                               \
    } while (0)

static const char *const kNames[10] = {"lazy_a1", "lazy_a2", "lazy_a3", "lazy_a4", "lazy_a5",
                                       "lazy_b1", "lazy_b2", "lazy_b3", "lazy_b4", "lazy_b5"};

static void mark_variable(char *out, size_t size, const char *name) {
    snprintf(out, size, "PEDNAV_TEST_OPENED_%s", name);
}

static int marks_set(void) {
    char var[64];
    int i, n = 0;
    for (i = 0; i < 10; ++i) {
        mark_variable(var, sizeof var, kNames[i]);
        if (getenv(var)) ++n;
    }
    return n;
}

static void clear_marks(void) {
    char var[64];
    int i;
    for (i = 0; i < 10; ++i) {
        mark_variable(var, sizeof var, kNames[i]);
        unsetenv(var);
    }
}

/* Libraries of the two directories loaded in this process right now. */
static int loaded(const char *const dirs[2]) {
    char path[4096];
    int i, n = 0;
    for (i = 0; i < 10; ++i) {
        void *h;
        snprintf(path, sizeof path, "%s/libpnp_%s.so", dirs[i / 5], kNames[i]);
        h = dlopen(path, RTLD_NOW | RTLD_NOLOAD);
        if (h) {
            ++n;
            dlclose(h);
        }
    }
    return n;
}

static int occurrences(const char *text, const char *needle) {
    int n = 0;
    const char *p = text;
    while ((p = strstr(p, needle)) != NULL) {
        ++n;
        p += strlen(needle);
    }
    return n;
}

/* The two-call idiom; returns a malloc'ed description or NULL. */
static char *describe(const char *const dirs[2], uint32_t flags) {
    size_t size = 0, again = 0;
    char *text;
    pn_error_t err;
    memset(&err, 0, sizeof err);
    err.struct_size = sizeof err;
    if (pn_plugins_describe(dirs, 2, flags, NULL, 0, &size, &err) != PN_E_INVALID_ARGUMENT || size < 2) return NULL;
    EXPECT(strstr(err.message, "bytes") != NULL); /* says how much is needed */
    text = (char *)malloc(size);
    if (!text) return NULL;
    if (pn_plugins_describe(dirs, 2, flags, text, size, &again, &err) != PN_OK || again != size ||
        strlen(text) + 1 != size) {
        free(text);
        return NULL;
    }
    return text;
}

int main(int argc, char **argv) {
    const char *dirs[2];
    char small[16];
    size_t size = 0;
    char *text;
    int i;
    pn_error_t err;
    if (argc != 3) {
        fprintf(stderr, "usage: plugins_describe_test LAZY_A_DIR LAZY_B_DIR\n");
        return 2;
    }
    dirs[0] = argv[1];
    dirs[1] = argv[2];
    clear_marks();

    /* Manifests only: every plugin, every library listed as not opened, no code run. */
    text = describe(dirs, 0);
    EXPECT(text != NULL);
    if (text) {
        EXPECT(occurrences(text, "\"kind\": \"step_detector\"") == 10);
        EXPECT(occurrences(text, "\"kind\": \"attitude_estimator\"") == 10);
        EXPECT(occurrences(text, "\"kind\": \"position_filter\"") == 10);
        EXPECT(occurrences(text, "\"opened\": false") == 10);
        EXPECT(occurrences(text, "\"opened\": true") == 0);
        EXPECT(occurrences(text, "libpnp_lazy_b4.json") == 1);
        for (i = 0; i < 10; ++i) {
            char id[64];
            snprintf(id, sizeof id, "\"org.pednav.test.%s.filter\"", kNames[i]);
            EXPECT(occurrences(text, id) == 2); /* in "plugins" and in its library's list */
        }
        EXPECT(strstr(text, "\"rejected\": []") != NULL);
        free(text);
    }
    EXPECT(marks_set() == 0);
    EXPECT(loaded(dirs) == 0);

    /* Opening every library: each one's initializer runs, all are closed again. */
    text = describe(dirs, PN_LIST_OPEN_LIBRARIES);
    EXPECT(text != NULL);
    if (text) {
        EXPECT(occurrences(text, "\"opened\": true") == 10);
        EXPECT(occurrences(text, "\"kind\": \"position_filter\"") == 10);
        free(text);
    }
    EXPECT(marks_set() == 10);
    EXPECT(loaded(dirs) == 0);

    /* A buffer too small: refused, the size given, the buffer left an empty string. */
    memset(&err, 0, sizeof err);
    err.struct_size = sizeof err;
    small[0] = 'x';
    EXPECT(pn_plugins_describe(dirs, 2, 0, small, sizeof small, &size, &err) == PN_E_INVALID_ARGUMENT);
    EXPECT(size > sizeof small);
    EXPECT(small[0] == '\0');
    EXPECT(strcmp(err.where, "buffer") == 0);

    /* Unknown flag bits and NULL directories: refused, naming the argument. */
    memset(&err, 0, sizeof err);
    err.struct_size = sizeof err;
    EXPECT(pn_plugins_describe(dirs, 2, 6u, NULL, 0, &size, &err) == PN_E_INVALID_ARGUMENT);
    EXPECT(strcmp(err.where, "flags") == 0);
    EXPECT(strstr(err.message, "unknown flag bits 6") != NULL);
    memset(&err, 0, sizeof err);
    err.struct_size = sizeof err;
    EXPECT(pn_plugins_describe(NULL, 1, 0, NULL, 0, &size, &err) == PN_E_INVALID_ARGUMENT);
    EXPECT(strcmp(err.where, "plugin_dirs") == 0);

    /* No directory at all: an empty description. */
    {
        char buffer[512];
        EXPECT(pn_plugins_describe(NULL, 0, PN_LIST_OPEN_LIBRARIES, buffer, sizeof buffer, &size, NULL) == PN_OK);
        EXPECT(strstr(buffer, "\"plugins\": []") != NULL);
        EXPECT(strstr(buffer, "\"libraries\": []") != NULL);
    }

    if (failures) fprintf(stderr, "%d expectation(s) failed\n", failures);
    else printf("pn_plugins_describe: 30 plugins listed from the manifests with nothing opened; 10 opened and closed\n");
    return failures ? 1 : 0;
}
