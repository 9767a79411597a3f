/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Layout sentinels of the pednav 1.x ABI on LP64 targets (x86_64, arm64).
 *
 * Compiled as C and as C++ by abi/tests/CMakeLists.txt, so a difference in
 * padding or in enum values between the two languages fails the build of the
 * test. The maintenance rule, which these assertions pin:
 *
 *     offsets never change;
 *     sizes only grow at the tail (a new minor may append fields);
 *     MIN sizes never grow within a major.
 *
 * When a minor appends a field: add its offset here and raise the sizeof
 * line; never edit an existing offset or a PNP_*_MIN_SIZE line. If one of
 * those fails, the change breaks every plugin and app already built.
 */
#include <pednav/pn_engine.h>
#include <pednav/pn_io.h>
#include <pednav/pn_plugin.h>
#include <pednav/pn_types.h>

#if defined(__cplusplus)
#define PN_SENTINEL(cond, name) static_assert(cond, #name)
#elif defined(__STDC_VERSION__) && __STDC_VERSION__ >= 201112L
#define PN_SENTINEL(cond, name) _Static_assert(cond, #name)
#else /* C99: a negative array size fails the compile */
#define PN_SENTINEL(cond, name) typedef char pn_sentinel_##name[(cond) ? 1 : -1]
#endif

#define PN_SIZE(type, size) PN_SENTINEL(sizeof(type) == (size), size_of_##type)
#define PN_OFF(type, field, off) PN_SENTINEL(offsetof(type, field) == (off), off_##type##_##field)
#define PN_ALIGN8(type) PN_SENTINEL(sizeof(type) % 8 == 0, align_of_##type)

/* The sentinels describe LP64 only. */
PN_SENTINEL(sizeof(void *) == 8 && sizeof(size_t) == 8 && sizeof(double) == 8, lp64_target);

/* ------------------------------------------------------------ constants */
PN_SENTINEL(PN_ABI_MAJOR == 1, abi_major);
PN_SENTINEL(PN_ABI_MINOR == 1, abi_minor);
PN_SENTINEL(PN_ABI_VERSION_MAJOR(PN_ABI_VERSION) == PN_ABI_MAJOR, abi_version_major);
PN_SENTINEL(PN_ABI_VERSION_MINOR(PN_ABI_VERSION) == PN_ABI_MINOR, abi_version_minor);
PN_SENTINEL(PN_RECORD_MAX_SIZE == 512, record_max_size);
PN_SENTINEL(PN_ERROR_WHERE_SIZE == 128, error_where_size);
PN_SENTINEL(PN_ERROR_MESSAGE_SIZE == 256, error_message_size);

/* Status codes and record type ids are ABI too: values never change. */
PN_SENTINEL(PN_OK == 0 && PN_NO_DATA == 1, status_success);
PN_SENTINEL(PN_E_INVALID_ARGUMENT == -1 && PN_E_INVALID_CONFIG == -2 && PN_E_UNSUPPORTED == -3 &&
                PN_E_ABI_MISMATCH == -4 && PN_E_NOT_FOUND == -5 && PN_E_BAD_STATE == -6 &&
                PN_E_OUT_OF_ORDER == -7 && PN_E_NUMERIC == -8 && PN_E_OUT_OF_MEMORY == -9 && PN_E_IO == -10 &&
                PN_E_INTERNAL == -11 && PN_E_BAD_INPUT == -12,
            status_failures);
PN_SENTINEL(PN_REC_IMU == 1 && PN_REC_MAG == 2 && PN_REC_BARO == 3 && PN_REC_GNSS == 4 &&
                PN_REC_GAIT_PHASE == 5 && PN_REC_STEP == 6 && PN_REC_ATTITUDE == 7 &&
                PN_REC_ATTITUDE_CORRECTION == 8 && PN_REC_POSITION == 9 && PN_REC_STRIDE == 10,
            record_type_ids);
PN_SENTINEL(PN_REC_TYPE_COUNT >= 11 && PN_REC_TYPE_COUNT <= 64, record_type_count);
PN_SENTINEL(PNP_KIND_STEP_DETECTOR == 1 && PNP_KIND_ATTITUDE_ESTIMATOR == 2 &&
                PNP_KIND_POSITION_FILTER == 3 && PNP_KIND_MAP_MATCHER == 4,
            plugin_kinds);

/* ---------------------------------------------------- MIN sizes (frozen) */
PN_SENTINEL(PNP_NODE_OPS_MIN_SIZE == 32, node_ops_min_size);
PN_SENTINEL(PNP_DESCRIPTOR_MIN_SIZE == 104, descriptor_min_size);
PN_SENTINEL(PNP_LIBRARY_MIN_SIZE == 56, library_min_size);
/* Record minimum sizes: the 1.0 sizes, pinned. */
PN_SENTINEL(PN_IMU_MIN_SIZE == 72, imu_min_size);
PN_SENTINEL(PN_MAG_MIN_SIZE == 48, mag_min_size);
PN_SENTINEL(PN_BARO_MIN_SIZE == 40, baro_min_size);
PN_SENTINEL(PN_GNSS_MIN_SIZE == 96, gnss_min_size);
PN_SENTINEL(PN_GAIT_PHASE_MIN_SIZE == 40, gait_phase_min_size);
PN_SENTINEL(PN_STEP_MIN_SIZE == 48, step_min_size);
PN_SENTINEL(PN_ATTITUDE_MIN_SIZE == 160, attitude_min_size);
PN_SENTINEL(PN_ATTITUDE_CORRECTION_MIN_SIZE == 72, attitude_correction_min_size);
PN_SENTINEL(PN_POSITION_MIN_SIZE == 160, position_min_size);
PN_SENTINEL(PN_STRIDE_MIN_SIZE == 152, stride_min_size);

/* ------------------------------------------------------- pn_types.h */
PN_OFF(pn_error_t, struct_size, 0);
PN_OFF(pn_error_t, code, 4);
PN_OFF(pn_error_t, detail, 8);
PN_OFF(pn_error_t, reserved, 12);
PN_OFF(pn_error_t, where, 16);
PN_OFF(pn_error_t, message, 144);
PN_SIZE(pn_error_t, 400);

/* 1.1 */
PN_OFF(pn_geo_point_t, lat_deg, 0);
PN_OFF(pn_geo_point_t, lon_deg, 8);
PN_OFF(pn_geo_point_t, height_m, 16);
PN_SIZE(pn_geo_point_t, 24);

PN_OFF(pn_record_header_t, struct_size, 0);
PN_OFF(pn_record_header_t, type, 4);
PN_OFF(pn_record_header_t, t_ns, 8);
PN_OFF(pn_record_header_t, source_id, 16);
PN_OFF(pn_record_header_t, flags, 20);
PN_SIZE(pn_record_header_t, 24);

PN_OFF(pn_imu_t, header, 0);
PN_OFF(pn_imu_t, accel_mps2, 24);
PN_OFF(pn_imu_t, gyro_radps, 48);
PN_SIZE(pn_imu_t, 72);

PN_OFF(pn_mag_t, mag_ut, 24);
PN_SIZE(pn_mag_t, 48);

PN_OFF(pn_baro_t, pressure_pa, 24);
PN_OFF(pn_baro_t, temperature_c, 32);
PN_SIZE(pn_baro_t, 40);

PN_OFF(pn_gnss_t, lat_deg, 24);
PN_OFF(pn_gnss_t, lon_deg, 32);
PN_OFF(pn_gnss_t, height_m, 40);
PN_OFF(pn_gnss_t, h_accuracy_m, 48);
PN_OFF(pn_gnss_t, v_accuracy_m, 56);
PN_OFF(pn_gnss_t, vel_enu_mps, 64);
PN_OFF(pn_gnss_t, utc_ns, 88);
PN_OFF(pn_gnss_t, satellites, 96);
PN_OFF(pn_gnss_t, fix_type, 100);
PN_SIZE(pn_gnss_t, 104);

PN_OFF(pn_gait_phase_t, stance, 24);
PN_OFF(pn_gait_phase_t, reserved, 28);
PN_OFF(pn_gait_phase_t, statistic, 32);
PN_SIZE(pn_gait_phase_t, 40);

PN_OFF(pn_step_t, t_start_ns, 24);
PN_OFF(pn_step_t, accel_peak_to_peak_mps2, 32);
PN_OFF(pn_step_t, frequency_hz, 40);
PN_OFF(pn_step_t, accel_max_mps2, 48);
PN_OFF(pn_step_t, accel_min_mps2, 56);
PN_OFF(pn_step_t, motion_mode, 64);
PN_OFF(pn_step_t, reserved, 68);
PN_SIZE(pn_step_t, 72);

PN_OFF(pn_attitude_t, q_enu_from_body, 24);
PN_OFF(pn_attitude_t, heading_rad, 56);
PN_OFF(pn_attitude_t, gyro_bias_radps, 64);
PN_OFF(pn_attitude_t, cov_attitude_rad2, 88);
PN_SIZE(pn_attitude_t, 160);

PN_OFF(pn_attitude_correction_t, rotation_enu_rad, 24);
PN_OFF(pn_attitude_correction_t, gyro_bias_delta_radps, 48);
PN_SIZE(pn_attitude_correction_t, 72);

PN_OFF(pn_position_t, pos_enu_m, 24);
PN_OFF(pn_position_t, vel_enu_mps, 48);
PN_OFF(pn_position_t, cov_enu_m2, 72);
PN_OFF(pn_position_t, heading_rad, 144);
PN_OFF(pn_position_t, floor, 152);
PN_OFF(pn_position_t, source, 156);
PN_OFF(pn_position_t, live_particles, 160);
PN_OFF(pn_position_t, recoveries, 164);
PN_SIZE(pn_position_t, 168);

PN_OFF(pn_stride_t, t_start_ns, 24);
PN_OFF(pn_stride_t, displacement_enu_m, 32);
PN_OFF(pn_stride_t, length_m, 56);
PN_OFF(pn_stride_t, heading_change_rad, 64);
PN_OFF(pn_stride_t, cov_displacement_m2, 72);
PN_OFF(pn_stride_t, stride_class, 144);
PN_OFF(pn_stride_t, index, 148);
PN_SIZE(pn_stride_t, 152);

/* Every record is 8-byte aligned in size and fits the output union. */
PN_ALIGN8(pn_imu_t);
PN_ALIGN8(pn_mag_t);
PN_ALIGN8(pn_baro_t);
PN_ALIGN8(pn_gnss_t);
PN_ALIGN8(pn_gait_phase_t);
PN_ALIGN8(pn_step_t);
PN_ALIGN8(pn_attitude_t);
PN_ALIGN8(pn_attitude_correction_t);
PN_ALIGN8(pn_position_t);
PN_ALIGN8(pn_stride_t);
PN_SENTINEL(sizeof(pn_gnss_t) <= PN_RECORD_MAX_SIZE && sizeof(pn_attitude_t) <= PN_RECORD_MAX_SIZE &&
                sizeof(pn_position_t) <= PN_RECORD_MAX_SIZE && sizeof(pn_stride_t) <= PN_RECORD_MAX_SIZE,
            records_fit_max_size);

/* ------------------------------------------------------- pn_plugin.h */
PN_OFF(pnp_host_t, abi_version, 0);
PN_OFF(pnp_host_t, struct_size, 4);
PN_OFF(pnp_host_t, host_data, 8);
PN_OFF(pnp_host_t, log, 16);
PN_OFF(pnp_host_t, get_origin, 24);   /* 1.1 */
PN_OFF(pnp_host_t, offer_origin, 32); /* 1.1 */
PN_SIZE(pnp_host_t, 40);

PN_OFF(pnp_sink_t, sink_data, 0);
PN_OFF(pnp_sink_t, emit, 8);
PN_SIZE(pnp_sink_t, 16);

PN_OFF(pnp_create_info_t, abi_version, 0);
PN_OFF(pnp_create_info_t, struct_size, 4);
PN_OFF(pnp_create_info_t, params_json, 8);
PN_OFF(pnp_create_info_t, params_len, 16);
PN_OFF(pnp_create_info_t, reserved, 20);
PN_OFF(pnp_create_info_t, instance_name, 24);
PN_OFF(pnp_create_info_t, mount, 32);
PN_OFF(pnp_create_info_t, imu_rate_hz, 40);
PN_SIZE(pnp_create_info_t, 48);

PN_OFF(pnp_node_ops_t, struct_size, 0);
PN_OFF(pnp_node_ops_t, reserved, 4);
PN_OFF(pnp_node_ops_t, destroy, 8);
PN_OFF(pnp_node_ops_t, reset, 16);
PN_OFF(pnp_node_ops_t, process, 24);
PN_OFF(pnp_node_ops_t, flush, 32);
PN_OFF(pnp_node_ops_t, reconfigure, 40);
PN_OFF(pnp_node_ops_t, latency_ns, 48);
PN_OFF(pnp_node_ops_t, reserved_slot, 56); /* 1.0's get_extension, withdrawn in 1.1 */
PN_SIZE(pnp_node_ops_t, 64);

PN_OFF(pnp_step_detector_ops_t, node, 0);
PN_SIZE(pnp_step_detector_ops_t, 64);
PN_OFF(pnp_attitude_estimator_ops_t, set_attitude, 64);
PN_SIZE(pnp_attitude_estimator_ops_t, 72);
PN_OFF(pnp_position_filter_ops_t, set_start, 64);
PN_SIZE(pnp_position_filter_ops_t, 72);
PN_OFF(pnp_map_matcher_ops_t, load_map, 64);
PN_OFF(pnp_map_matcher_ops_t, set_start, 72);
PN_SIZE(pnp_map_matcher_ops_t, 80);

PN_OFF(pnp_descriptor_t, abi_version, 0);
PN_OFF(pnp_descriptor_t, struct_size, 4);
PN_OFF(pnp_descriptor_t, id, 8);
PN_OFF(pnp_descriptor_t, name, 16);
PN_OFF(pnp_descriptor_t, version, 24);
PN_OFF(pnp_descriptor_t, vendor, 32);
PN_OFF(pnp_descriptor_t, description, 40);
PN_OFF(pnp_descriptor_t, features, 48);
PN_OFF(pnp_descriptor_t, params_schema_json, 56);
PN_OFF(pnp_descriptor_t, kind, 64);
PN_OFF(pnp_descriptor_t, kind_version, 68);
PN_OFF(pnp_descriptor_t, consumes, 72);
PN_OFF(pnp_descriptor_t, produces, 80);
PN_OFF(pnp_descriptor_t, create, 88);
PN_OFF(pnp_descriptor_t, ops, 96);
PN_SIZE(pnp_descriptor_t, 104);

PN_OFF(pnp_library_t, abi_version, 0);
PN_OFF(pnp_library_t, struct_size, 4);
PN_OFF(pnp_library_t, id, 8);
PN_OFF(pnp_library_t, version, 16);
PN_OFF(pnp_library_t, init, 24);
PN_OFF(pnp_library_t, deinit, 32);
PN_OFF(pnp_library_t, plugin_count, 40);
PN_OFF(pnp_library_t, reserved, 44);
PN_OFF(pnp_library_t, plugins, 48);
PN_SIZE(pnp_library_t, 56);

/* ------------------------------------------------------- pn_engine.h */
PN_OFF(pn_engine_create_info_t, abi_version, 0);
PN_OFF(pn_engine_create_info_t, struct_size, 4);
PN_OFF(pn_engine_create_info_t, config_json, 8);
PN_OFF(pn_engine_create_info_t, config_len, 16);
PN_OFF(pn_engine_create_info_t, plugin_dirs, 24);
PN_OFF(pn_engine_create_info_t, plugin_dir_count, 32);
PN_OFF(pn_engine_create_info_t, static_library_count, 36);
PN_OFF(pn_engine_create_info_t, static_libraries, 40);
PN_OFF(pn_engine_create_info_t, log, 48);
PN_OFF(pn_engine_create_info_t, log_user, 56);
PN_OFF(pn_engine_create_info_t, output_queue_capacity, 64);
PN_OFF(pn_engine_create_info_t, reserved, 68);
PN_SIZE(pn_engine_create_info_t, 72);

PN_SIZE(pn_output_t, PN_RECORD_MAX_SIZE);
PN_OFF(pn_output_t, header, 0);
PN_OFF(pn_output_t, position, 0);
PN_OFF(pn_output_t, bytes, 0);

/* --------------------------------------------------------- pn_io.h */
PN_OFF(pn_truth_point_t, t_s, 0);
PN_OFF(pn_truth_point_t, pos_enu_m, 8);
PN_OFF(pn_truth_point_t, floor, 32);
PN_OFF(pn_truth_point_t, has_z, 36);
PN_SIZE(pn_truth_point_t, 40);

int pn_layout_sentinels_probe(void);
int pn_layout_sentinels_probe(void) { return 0; }
