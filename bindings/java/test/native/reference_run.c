/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The reference the Java recording test compares against: reads a recording
 * with the engine's readers (pn_io.h), writes its input records as text with
 * every double in C99 hex (%a, exact), runs them through pn_engine_push_records
 * with the given config, 1024 records per call and polling between calls as
 * `pednav run` does (the output queue holds 8192 records), and writes every
 * polled position the same way.
 *
 *   reference_run CONFIG.json RECORDING PLUGIN_DIR INPUTS.txt POSITIONS.txt
 *
 * INPUTS.txt, one record a line: "imu t_ns ax ay az gx gy gz", "mag t_ns mx my mz",
 * "baro t_ns pressure_pa temperature_c", "gnss t_ns lat lon height h_acc v_acc".
 * POSITIONS.txt: "t_ns east north up heading_rad".
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <pednav/pn_engine.h>
#include <pednav/pn_io.h>

static char *read_file(const char *path) {
    FILE *f = fopen(path, "rb");
    char *text;
    long n;
    if (!f) return NULL;
    if (fseek(f, 0, SEEK_END) != 0 || (n = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        return NULL;
    }
    text = (char *)malloc((size_t)n + 1);
    if (text && fread(text, 1, (size_t)n, f) != (size_t)n) {
        free(text);
        text = NULL;
    }
    if (text) text[n] = '\0';
    fclose(f);
    return text;
}

static int write_inputs(const char *path, const pn_record_header_t *const *records, size_t count) {
    FILE *f = fopen(path, "w");
    size_t i;
    if (!f) return 0;
    for (i = 0; i < count; ++i) {
        const pn_record_header_t *h = records[i];
        const long long t = (long long)h->t_ns;
        if (h->type == PN_REC_IMU) {
            const pn_imu_t *r = (const pn_imu_t *)h;
            fprintf(f, "imu %lld %a %a %a %a %a %a\n", t, r->accel_mps2[0], r->accel_mps2[1],
                    r->accel_mps2[2], r->gyro_radps[0], r->gyro_radps[1], r->gyro_radps[2]);
        } else if (h->type == PN_REC_MAG) {
            const pn_mag_t *r = (const pn_mag_t *)h;
            fprintf(f, "mag %lld %a %a %a\n", t, r->mag_ut[0], r->mag_ut[1], r->mag_ut[2]);
        } else if (h->type == PN_REC_BARO) {
            const pn_baro_t *r = (const pn_baro_t *)h;
            fprintf(f, "baro %lld %a %a\n", t, r->pressure_pa, r->temperature_c);
        } else if (h->type == PN_REC_GNSS) {
            const pn_gnss_t *r = (const pn_gnss_t *)h;
            if (h->flags != 0 || r->utc_ns != 0) {
                fprintf(stderr,
                        "reference_run: record %zu: a GNSS fix with velocity or UTC has no text form here\n",
                        i);
                fclose(f);
                return 0;
            }
            fprintf(f, "gnss %lld %a %a %a %a %a\n", t, r->lat_deg, r->lon_deg, r->height_m, r->h_accuracy_m,
                    r->v_accuracy_m);
        }
    }
    return fclose(f) == 0;
}

int main(int argc, char **argv) {
    pn_recording_t *rec = NULL;
    pn_engine_t *engine = NULL;
    pn_engine_create_info_t info;
    pn_error_t err;
    const pn_record_header_t *const *records = NULL;
    const char *dirs[1];
    pn_output_t out;
    size_t count = 0, positions = 0, start;
    char *config;
    FILE *f;
    if (argc != 6) {
        fprintf(stderr, "usage: reference_run CONFIG.json RECORDING PLUGIN_DIR INPUTS.txt POSITIONS.txt\n");
        return 2;
    }
    config = read_file(argv[1]);
    if (!config) {
        fprintf(stderr, "reference_run: cannot read %s\n", argv[1]);
        return 1;
    }
    memset(&err, 0, sizeof err);
    err.struct_size = sizeof err;
    if (pn_recording_open(argv[2], "auto", NULL, &rec, &err) != PN_OK ||
        pn_recording_merged(rec, &records, &count) != PN_OK) {
        fprintf(stderr, "reference_run: %s: %s\n", err.where, err.message);
        return 1;
    }
    if (!write_inputs(argv[4], records, count)) {
        fprintf(stderr, "reference_run: cannot write %s\n", argv[4]);
        return 1;
    }
    dirs[0] = argv[3];
    memset(&info, 0, sizeof info);
    info.abi_version = PN_ABI_VERSION;
    info.struct_size = sizeof info;
    info.config_json = config;
    info.plugin_dirs = dirs;
    info.plugin_dir_count = 1;
    if (pn_engine_create(&info, &engine, &err) != PN_OK) {
        fprintf(stderr, "reference_run: %s: %s\n", err.where, err.message);
        return 1;
    }
    f = fopen(argv[5], "w");
    if (!f) {
        fprintf(stderr, "reference_run: cannot write %s\n", argv[5]);
        return 1;
    }
    for (start = 0; start <= count; start += 1024) {
        const size_t n = count - start < 1024 ? count - start : 1024;
        if ((n > 0 && pn_engine_push_records(engine, records + start, n, &err) != PN_OK) ||
            (n < 1024 && pn_engine_flush(engine, &err) != PN_OK)) {
            fprintf(stderr, "reference_run: %s: %s (record %zu)\n", err.where, err.message,
                    start + (size_t)err.detail);
            return 1;
        }
        while (pn_engine_poll(engine, &out) == PN_OK) {
            if (out.header.type != PN_REC_POSITION) continue;
            fprintf(f, "%lld %a %a %a %a\n", (long long)out.header.t_ns, out.position.pos_enu_m[0],
                    out.position.pos_enu_m[1], out.position.pos_enu_m[2], out.position.heading_rad);
            ++positions;
        }
    }
    if (fclose(f) != 0) return 1;
    printf("reference_run: %zu input records, %zu positions\n", count, positions);
    pn_engine_destroy(engine);
    pn_recording_destroy(rec);
    free(config);
    return positions > 0 ? 0 : 1;
}
