/* SPDX-License-Identifier: Apache-2.0 */
/* An app on the installed C API: pushes 50 IMU samples and prints how many
 * steps came out (10 expected). Built twice: on libpednav.so, loading the
 * consumer plugin from the directory argv[1]; and with CONSUMER_STATIC on the
 * static engine (pednav::pednav_static) with the plugin's static library
 * linked in, handed over as pnp_entry_v1_consumer_steps() (no directory). */
#include <stdio.h>
#include <string.h>

#include <pednav/pn_engine.h>

#ifdef CONSUMER_STATIC
const pnp_library_t *pnp_entry_v1_consumer_steps(void);
#define CONSUMER_NAME "static consumer"
#else
#define CONSUMER_NAME "consumer"
#endif

int main(int argc, char **argv) {
    const char *config =
        "{\"format\": \"pednav-config/1\", \"mount\": \"waist\", \"pipelines\": {\"waist\": {"
        "\"step_detector\": {\"plugin\": \"com.example.consumer.every_n\", \"params\": {\"every_n\": 5}}}}}";
    pn_engine_create_info_t info;
    pn_engine_t *engine = NULL;
    pn_error_t err;
    pn_imu_t samples[50];
    pn_output_t out;
    int i, steps = 0;
#ifdef CONSUMER_STATIC
    const pnp_library_t *libraries[1];
    (void)argc;
    (void)argv;
    libraries[0] = pnp_entry_v1_consumer_steps();
#else
    if (argc < 2) return 2;
#endif
    memset(&err, 0, sizeof err);
    err.struct_size = sizeof err;
    memset(&info, 0, sizeof info);
    info.abi_version = PN_ABI_VERSION;
    info.struct_size = sizeof info;
    info.config_json = config;
#ifdef CONSUMER_STATIC
    info.static_libraries = libraries;
    info.static_library_count = 1;
#else
    info.plugin_dirs = (const char *const *)&argv[1];
    info.plugin_dir_count = 1;
#endif
    if (pn_engine_create(&info, &engine, &err) != PN_OK) {
        fprintf(stderr, "create failed: %s at %s\n", err.message, err.where);
        return 1;
    }
    memset(samples, 0, sizeof samples);
    for (i = 0; i < 50; ++i) {
        samples[i].header.struct_size = sizeof(pn_imu_t);
        samples[i].header.type = PN_REC_IMU;
        samples[i].header.t_ns = 1000000000 + (int64_t)i * 10000000;
        samples[i].accel_mps2[2] = 9.81;
    }
    if (pn_engine_push_imu(engine, samples, 50, sizeof(pn_imu_t), &err) != PN_OK ||
        pn_engine_flush(engine, &err) != PN_OK) {
        fprintf(stderr, "push failed: %s\n", err.message);
        pn_engine_destroy(engine);
        return 1;
    }
    while (pn_engine_poll(engine, &out) == PN_OK)
        if (out.header.type == PN_REC_STEP) ++steps;
    pn_engine_destroy(engine);
    printf(CONSUMER_NAME ": %d steps from pednav %s\n", steps, pn_version_string());
    return steps == 10 ? 0 : 1;
}
