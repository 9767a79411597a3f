/* SPDX-License-Identifier: Apache-2.0 */
/*
 * pednav C API example: embed the engine in a C99 program using only
 * <pednav/pn_engine.h>.
 *
 *   pednav_c_api_example PLUGIN_DIR [CONFIG_FILE]
 *
 * Creates an engine from a config string (or CONFIG_FILE), pushes a synthetic
 * 2 s walk at 100 Hz from an app-side array whose elements are larger than
 * pn_imu_t (so the stride is explicit), polls steps and positions, prints
 * them, and checks every status. Exit code 0 on success.
 *
 * With no CONFIG_FILE it uses the test plugins built in
 * <build>/test-plugins/good: a step every 10 samples, 0.7 m per step.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <pednav/pn_engine.h>

static const char *const kDefaultConfig =
    "{\"format\": \"pednav-config/1\", \"mount\": \"foot\", \"pipelines\": {\"foot\": {"
    "\"step_detector\": {\"plugin\": \"org.pednav.test.counting_steps\", \"params\": {\"every_n\": 10}},"
    "\"position_filter\": {\"plugin\": \"org.pednav.test.step_counter\", \"params\": {\"step_length_m\": "
    "0.7}}"
    "}}}";

/* What an app might keep per sample: the record plus its own bookkeeping. */
typedef struct app_sample_t {
    pn_imu_t imu;
    uint32_t sequence;
    uint32_t sensor_id;
} app_sample_t;

#define SAMPLE_COUNT 200
#define RATE_HZ 100.0

static void log_line(void *user, int32_t level, const char *source, const char *msg) {
    (void)user;
    if (level >= 2) fprintf(stderr, "[%s] %s\n", source, msg);
}

static int check(pn_status_t status, const pn_error_t *err, const char *what) {
    if (!PN_FAILED(status)) return 1;
    fprintf(stderr, "%s failed: %s (where: %s, detail: %d): %s\n", what, pn_status_name(status), err->where,
            (int)err->detail, err->message);
    return 0;
}

static char *read_file(const char *path) {
    FILE *f = fopen(path, "rb");
    char *text;
    long size;
    if (!f) return NULL;
    if (fseek(f, 0, SEEK_END) != 0 || (size = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        return NULL;
    }
    text = (char *)malloc((size_t)size + 1);
    if (text && fread(text, 1, (size_t)size, f) != (size_t)size) {
        free(text);
        text = NULL;
    }
    if (text) text[size] = '\0';
    fclose(f);
    return text;
}

int main(int argc, char **argv) {
    static app_sample_t samples[SAMPLE_COUNT];
    const double pi = 3.14159265358979323846;
    const char *dirs[1];
    char *config_file = NULL;
    pn_engine_create_info_t info;
    pn_engine_t *engine = NULL;
    pn_error_t err;
    pn_output_t out;
    pn_status_t status;
    int steps = 0, positions = 0, ok = 1;
    double last_east = 0.0, last_north = 0.0;
    size_t i;

    if (argc < 2) {
        fprintf(stderr, "usage: %s PLUGIN_DIR [CONFIG_FILE]\n", argv[0]);
        return 2;
    }
    if (argc > 2 && !(config_file = read_file(argv[2]))) {
        fprintf(stderr, "cannot read %s\n", argv[2]);
        return 2;
    }
    printf("pednav %s, ABI %u.%u\n", pn_version_string(), (unsigned)PN_ABI_VERSION_MAJOR(pn_abi_version()),
           (unsigned)PN_ABI_VERSION_MINOR(pn_abi_version()));

    memset(&err, 0, sizeof err);
    err.struct_size = sizeof err;
    memset(&info, 0, sizeof info);
    info.abi_version = PN_ABI_VERSION;
    info.struct_size = sizeof info;
    info.config_json = config_file ? config_file : kDefaultConfig;
    info.config_len = 0; /* NUL-terminated */
    dirs[0] = argv[1];
    info.plugin_dirs = dirs;
    info.plugin_dir_count = 1;
    info.log = log_line;
    status = pn_engine_create(&info, &engine, &err);
    free(config_file);
    if (!check(status, &err, "pn_engine_create")) return 1;
    printf("latency: %.3f s\n", (double)pn_engine_latency_ns(engine) * 1e-9);

    /* A walk: gravity plus a 2 Hz bounce, time from 1 s at 100 Hz. */
    for (i = 0; i < SAMPLE_COUNT; ++i) {
        const double t = (double)i / RATE_HZ;
        pn_imu_t *s = &samples[i].imu;
        memset(&samples[i], 0, sizeof samples[i]);
        s->header.struct_size = sizeof(pn_imu_t);
        s->header.type = PN_REC_IMU;
        s->header.t_ns = 1000000000 + (int64_t)i * 10000000;
        s->accel_mps2[2] = 9.81 + 1.5 * cos(2.0 * pi * 2.0 * t);
        s->gyro_radps[2] = 0.01;
        samples[i].sequence = (uint32_t)i;
        samples[i].sensor_id = 7;
    }
    /* Push in two batches; the stride skips the app's own fields. */
    status = pn_engine_push_imu(engine, &samples[0].imu, SAMPLE_COUNT / 2, sizeof(app_sample_t), &err);
    ok = ok && check(status, &err, "pn_engine_push_imu");
    status = pn_engine_push_imu(engine, &samples[SAMPLE_COUNT / 2].imu, SAMPLE_COUNT / 2,
                                sizeof(app_sample_t), &err);
    ok = ok && check(status, &err, "pn_engine_push_imu");
    status = pn_engine_flush(engine, &err);
    ok = ok && check(status, &err, "pn_engine_flush");

    while ((status = pn_engine_poll(engine, &out)) == PN_OK) {
        const double t_s = (double)out.header.t_ns * 1e-9;
        if (out.header.type == PN_REC_STEP) {
            ++steps;
            printf("step %d at t=%.2f s\n", steps, t_s);
        } else if (out.header.type == PN_REC_POSITION) {
            ++positions;
            last_east = out.position.pos_enu_m[0];
            last_north = out.position.pos_enu_m[1];
            printf("position at t=%.2f s: east %.3f m, north %.3f m, sigma %.3f m\n", t_s, last_east,
                   last_north, sqrt(out.position.cov_enu_m2[0] + out.position.cov_enu_m2[4]));
        }
    }
    if (status != PN_NO_DATA) ok = ok && check(status, &err, "pn_engine_poll");

    { /* Describe with the two-call size idiom. */
        size_t size = 0;
        char *text;
        if (pn_engine_describe(engine, NULL, 0, &size) != PN_E_INVALID_ARGUMENT || size == 0) ok = 0;
        text = (char *)malloc(size);
        if (!text || pn_engine_describe(engine, text, size, &size) != PN_OK) {
            fprintf(stderr, "pn_engine_describe failed\n");
            ok = 0;
        } else
            printf("describe: %lu bytes of JSON\n", (unsigned long)(size - 1));
        free(text);
    }
    pn_engine_destroy(engine);

    printf("summary: %d steps, %d positions, last at east %.3f m, north %.3f m, %s\n", steps, positions,
           last_east, last_north, ok ? "all statuses ok" : "FAILED");
    return ok ? 0 : 1;
}
