/* SPDX-License-Identifier: Apache-2.0 */
/*
 * An app that cannot dlopen (iOS): the engine (libpednav.a) and the three foot
 * plugins (libpnp_foot_*.a) linked in, the plugin libraries handed to the
 * engine as pnp_entry_v1_<name>(), no plugin directory.
 *
 *   static_foot_app CONFIG.json INPUT.csv PLUGIN_DIR
 *
 * Runs the simulated walk INPUT.csv (canonical CSV of `pednav sim`: t, accel,
 * gyro, magnetometer) through the foot preset twice: with the linked-in
 * libraries, and with the same plugins loaded from PLUGIN_DIR. The two runs
 * must give the same records, byte for byte, and the walk (a closed 120 m
 * corridor loop of 86 strides) must close: all 86 strides found, the last
 * position within 0.6 m (0.5 %) of the first, the strides adding up to the
 * loop's length within 3 %.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <pednav/pn_engine.h>

/* The entry functions of the static plugin libraries (pednav_add_plugin NAME). */
const pnp_library_t *pnp_entry_v1_foot_stance(void);
const pnp_library_t *pnp_entry_v1_foot_strapdown(void);
const pnp_library_t *pnp_entry_v1_foot_ekf(void);

typedef struct sample_t {
    pn_imu_t imu;
    pn_mag_t mag;
} sample_t;

typedef struct run_t {
    pn_output_t *outputs;
    size_t count, capacity;
} run_t;

static char *read_file(const char *path) {
    FILE *f = fopen(path, "rb");
    long size;
    char *text;
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    size = ftell(f);
    fseek(f, 0, SEEK_SET);
    text = (char *)malloc((size_t)size + 1);
    if (text && fread(text, 1, (size_t)size, f) != (size_t)size) {
        free(text);
        text = NULL;
    }
    if (text) text[size] = '\0';
    fclose(f);
    return text;
}

/* Rows t,ax,ay,az,gx,gy,gz,mx,my,mz[,p]; comment and header lines skipped. */
static sample_t *read_walk(const char *path, size_t *count) {
    FILE *f = fopen(path, "r");
    char line[512];
    size_t n = 0, capacity = 0;
    sample_t *samples = NULL;
    if (!f) return NULL;
    while (fgets(line, sizeof line, f)) {
        double v[10];
        sample_t *s;
        if (line[0] == '#' || line[0] == 't') continue;
        if (sscanf(line, "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5], &v[6],
                   &v[7], &v[8], &v[9]) != 10) {
            fprintf(stderr, "%s: row %zu is not t,ax,ay,az,gx,gy,gz,mx,my,mz\n", path, n + 1);
            free(samples);
            fclose(f);
            return NULL;
        }
        if (n == capacity) {
            sample_t *grown;
            capacity = capacity ? 2 * capacity : 4096;
            grown = (sample_t *)realloc(samples, capacity * sizeof *samples);
            if (!grown) {
                free(samples);
                fclose(f);
                return NULL;
            }
            samples = grown;
        }
        s = &samples[n++];
        memset(s, 0, sizeof *s);
        s->imu.header.struct_size = sizeof s->imu;
        s->imu.header.type = PN_REC_IMU;
        s->imu.header.t_ns = (int64_t)llround(v[0] * 1e9);
        memcpy(s->imu.accel_mps2, &v[1], sizeof s->imu.accel_mps2);
        memcpy(s->imu.gyro_radps, &v[4], sizeof s->imu.gyro_radps);
        s->mag.header.struct_size = sizeof s->mag;
        s->mag.header.type = PN_REC_MAG;
        s->mag.header.t_ns = s->imu.header.t_ns;
        memcpy(s->mag.mag_ut, &v[7], sizeof s->mag.mag_ut);
    }
    fclose(f);
    *count = n;
    return samples;
}

/* Polls every output queued into run. 0 on success. */
static int drain(pn_engine_t *engine, run_t *run) {
    for (;;) {
        if (run->count == run->capacity) {
            pn_output_t *grown;
            run->capacity = run->capacity ? 2 * run->capacity : 16384;
            grown = (pn_output_t *)realloc(run->outputs, run->capacity * sizeof *grown);
            if (!grown) return 1;
            run->outputs = grown;
        }
        if (pn_engine_poll(engine, &run->outputs[run->count]) != PN_OK) return 0;
        ++run->count;
    }
}

/* True when the engine describes three linked-in libraries and nothing else. */
static int three_static_libraries(const pn_engine_t *engine) {
    size_t size = 0;
    char *text;
    int ok;
    pn_engine_describe(engine, NULL, 0, &size);
    text = (char *)malloc(size ? size : 1);
    if (!text || pn_engine_describe(engine, text, size, &size) != PN_OK) {
        free(text);
        return 0;
    }
    ok = strstr(text, "\"<static:2>\"") && !strstr(text, "\"<static:3>\"") && strstr(text, "\"rejected\": []") &&
         !strstr(text, ".so\"");
    if (!ok) fprintf(stderr, "the static engine does not describe three linked-in libraries alone:\n%s\n", text);
    free(text);
    return ok;
}

/* Creates an engine, pushes the walk, keeps every output. 0 on success. */
static int run_walk(const char *config, const char *plugin_dir, const sample_t *samples, size_t count,
                    run_t *run) {
    const pnp_library_t *libraries[3];
    pn_engine_create_info_t info;
    pn_engine_t *engine = NULL;
    pn_error_t err;
    size_t i;
    int failed = 0;
    memset(&err, 0, sizeof err);
    err.struct_size = sizeof err;
    memset(&info, 0, sizeof info);
    info.abi_version = PN_ABI_VERSION;
    info.struct_size = sizeof info;
    info.config_json = config;
    if (plugin_dir) {
        info.plugin_dirs = &plugin_dir;
        info.plugin_dir_count = 1;
    } else {
        libraries[0] = pnp_entry_v1_foot_stance();
        libraries[1] = pnp_entry_v1_foot_strapdown();
        libraries[2] = pnp_entry_v1_foot_ekf();
        info.static_libraries = libraries;
        info.static_library_count = 3;
    }
    if (pn_engine_create(&info, &engine, &err) != PN_OK) {
        fprintf(stderr, "create (%s) failed: %s at %s\n", plugin_dir ? "loaded" : "linked-in", err.message, err.where);
        return 1;
    }
    if (!plugin_dir && !three_static_libraries(engine)) failed = 1;
    for (i = 0; i < count && !failed; ++i) {
        if (pn_engine_push(engine, &samples[i].imu.header, &err) != PN_OK ||
            pn_engine_push(engine, &samples[i].mag.header, &err) != PN_OK) {
            fprintf(stderr, "push of sample %zu failed: %s at %s\n", i, err.message, err.where);
            failed = 1;
        }
        failed = failed || drain(engine, run);
    }
    if (!failed && pn_engine_flush(engine, &err) != PN_OK) {
        fprintf(stderr, "flush failed: %s\n", err.message);
        failed = 1;
    }
    failed = failed || drain(engine, run);
    pn_engine_destroy(engine);
    return failed;
}

int main(int argc, char **argv) {
    char *config;
    sample_t *samples;
    size_t count = 0, i, positions = 0, strides = 0, first = 0, last = 0;
    double stride_length_m = 0, closure_m;
    run_t linked = {NULL, 0, 0}, loaded = {NULL, 0, 0};
    int failed = 0;
    if (argc != 4) {
        fprintf(stderr, "usage: static_foot_app CONFIG.json INPUT.csv PLUGIN_DIR\n");
        return 2;
    }
    config = read_file(argv[1]);
    samples = read_walk(argv[2], &count);
    if (!config || !samples || count < 1000) {
        fprintf(stderr, "cannot read the config %s or the walk %s (%zu samples)\n", argv[1], argv[2], count);
        return 1;
    }
    if (run_walk(config, NULL, samples, count, &linked) || run_walk(config, argv[3], samples, count, &loaded))
        return 1;

    if (linked.count != loaded.count) {
        fprintf(stderr, "linked-in run: %zu records, loaded run: %zu\n", linked.count, loaded.count);
        failed = 1;
    }
    for (i = 0; i < linked.count && i < loaded.count; ++i)
        if (linked.outputs[i].header.struct_size != loaded.outputs[i].header.struct_size ||
            memcmp(&linked.outputs[i], &loaded.outputs[i], linked.outputs[i].header.struct_size) != 0) {
            fprintf(stderr, "record %zu differs between the linked-in and the loaded plugins\n", i);
            failed = 1;
            break;
        }

    for (i = 0; i < linked.count; ++i) {
        const pn_output_t *o = &linked.outputs[i];
        if (o->header.type == PN_REC_POSITION) {
            if (positions++ == 0) first = i;
            last = i;
        } else if (o->header.type == PN_REC_STRIDE) {
            ++strides;
            stride_length_m += o->stride.length_m;
        }
    }
    closure_m = positions ? hypot(linked.outputs[last].position.pos_enu_m[0] - linked.outputs[first].position.pos_enu_m[0],
                                  linked.outputs[last].position.pos_enu_m[1] - linked.outputs[first].position.pos_enu_m[1])
                          : INFINITY;
    printf("%zu samples: %zu positions, %zu strides, %.2f m of strides, loop closes within %.3f m; "
           "linked-in and loaded plugins give the same %zu records: %s\n",
           count, positions, strides, stride_length_m, closure_m, linked.count, failed ? "no" : "yes");
    /* A position per sample after the alignment's first second; every one of the walk's 86 strides. */
    if (positions < count * 9 / 10 || strides != 86) {
        fprintf(stderr, "expected a position per sample after the alignment and 86 strides\n");
        failed = 1;
    }
    if (!(closure_m < 0.6) || fabs(stride_length_m - 120.0) > 3.6) {
        fprintf(stderr, "the 120 m loop does not close: %.3f m apart, %.2f m of strides\n", closure_m, stride_length_m);
        failed = 1;
    }
    free(linked.outputs);
    free(loaded.outputs);
    free(samples);
    free(config);
    return failed;
}
