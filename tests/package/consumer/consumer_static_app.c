/* SPDX-License-Identifier: Apache-2.0 */
/* An app with the installed static engine (pednav::pednav_static) and the
 * consumer plugin's static library linked in: no plugin directory, the
 * library handed over as pnp_entry_v1_consumer_steps(). Pushes 50 IMU samples
 * and prints how many steps came out (10 expected). */
#include <stdio.h>
#include <string.h>

#include <pednav/pn_engine.h>

const pnp_library_t *pnp_entry_v1_consumer_steps(void);

int main(void) {
    const char *config =
        "{\"format\": \"pednav-config/1\", \"mount\": \"waist\", \"pipelines\": {\"waist\": {"
        "\"step_detector\": {\"plugin\": \"com.example.consumer.every_n\", \"params\": {\"every_n\": 5}}}}}";
    const pnp_library_t *libraries[1];
    pn_engine_create_info_t info;
    pn_engine_t *engine = NULL;
    pn_error_t err;
    pn_imu_t samples[50];
    pn_output_t out;
    int i, steps = 0;
    memset(&err, 0, sizeof err);
    err.struct_size = sizeof err;
    libraries[0] = pnp_entry_v1_consumer_steps();
    memset(&info, 0, sizeof info);
    info.abi_version = PN_ABI_VERSION;
    info.struct_size = sizeof info;
    info.config_json = config;
    info.static_libraries = libraries;
    info.static_library_count = 1;
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
    printf("static consumer: %d steps from pednav %s\n", steps, pn_version_string());
    return steps == 10 ? 0 : 1;
}
