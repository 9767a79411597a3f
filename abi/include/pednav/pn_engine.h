/* SPDX-License-Identifier: Apache-2.0 */
/*
 * pednav stable C ABI, part 3 of 3: the app-facing engine API.
 *
 * An app creates an engine from a JSON config and a list of plugin
 * directories, pushes sensor samples, and polls outputs. Processing runs
 * inside the push calls on the caller's thread, so the same input and config
 * give bit-identical output (replays of field recordings reproduce bugs).
 *
 * Threading. Every function carries one of these tags:
 *   [thread-safe] any thread, concurrently, engine or not;
 *   [producer]    the thread that pushes: calls on one engine with this tag
 *                 must not overlap each other (the engine does not lock);
 *   [consumer]    one other thread may poll while the producer pushes
 *                 (single-producer, single-consumer output queue);
 *   [any thread]  any thread, also while the producer and consumer run;
 *   [exclusive]   no other call on this engine may be running.
 * Different engines are independent.
 *
 * Every function accepts err == NULL. No function returns memory the caller
 * must free; text goes into caller buffers with the two-call size idiom.
 * A call that cannot take effect says so (PN_E_BAD_STATE, PN_E_UNSUPPORTED,
 * PN_E_INVALID_ARGUMENT) and changes nothing.
 */
#ifndef PEDNAV_PN_ENGINE_H
#define PEDNAV_PN_ENGINE_H

#include <stddef.h>
#include <stdint.h>

#include "pn_plugin.h"
#include "pn_types.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Building libpednav defines PEDNAV_BUILDING_LIBRARY; an app linking the
 * static engine (pednav::pednav_static) gets PEDNAV_STATIC from the target. */
#if defined(_WIN32) && defined(PEDNAV_BUILDING_LIBRARY) && !defined(PEDNAV_STATIC)
#define PN_API __declspec(dllexport)
#elif defined(_WIN32) && !defined(PEDNAV_STATIC)
#define PN_API __declspec(dllimport)
#elif defined(__GNUC__) && defined(PEDNAV_BUILDING_LIBRARY)
#define PN_API __attribute__((visibility("default")))
#else
#define PN_API
#endif

typedef struct pn_engine_t pn_engine_t; /* opaque */

/* Log callback, called on the thread of the engine call that logs (also from
 * within pn_engine_create, while plugins initialise); msg borrowed for the
 * call. `source` is "engine", an instance name such as "foot/position_filter",
 * or a plugin library id (lines its init writes). */
typedef void (*pn_log_fn)(void *user, int32_t level, const char *source, const char *msg);

typedef struct pn_engine_create_info_t {
    uint32_t abi_version;  /* PN_ABI_VERSION */
    uint32_t struct_size;  /* sizeof(pn_engine_create_info_t) */
    const char *config_json;       /* the whole config document, UTF-8 */
    size_t config_len;             /* bytes; 0 = NUL-terminated */
    const char *const *plugin_dirs; /* directories searched for libpnp_*.so, in order */
    uint32_t plugin_dir_count;
    uint32_t static_library_count;
    const pnp_library_t *const *static_libraries; /* linked-in plugin libraries (iOS, tests) */
    pn_log_fn log;                 /* may be NULL */
    void *log_user;
    uint32_t output_queue_capacity; /* records kept until polled; 0 = 8192, at most
                                       PN_OUTPUT_QUEUE_MAX. When full, new outputs are dropped
                                       and counted in describe (counters.outputs_dropped);
                                       get_latest still sees them. */
    uint32_t reserved;
} pn_engine_create_info_t;

#define PN_OUTPUT_QUEUE_MAX 1048576u /* 512 MiB of 512-byte slots */

/* Outputs are polled one record at a time into this union. */
typedef union pn_output_t {
    pn_record_header_t header; /* header.type says which member is valid */
    pn_position_t position;
    pn_stride_t stride;
    pn_step_t step;
    pn_attitude_t attitude;
    pn_gait_phase_t gait_phase;
    unsigned char bytes[PN_RECORD_MAX_SIZE];
} pn_output_t;

/* ----------------------------------------------------------- versions */

/* [thread-safe] Version of the library and its ABI. */
PN_API uint32_t pn_abi_version(void);
PN_API const char *pn_version_string(void);
/* [thread-safe] Name of a status code ("PN_E_INVALID_CONFIG"); never NULL. */
PN_API const char *pn_status_name(pn_status_t status);

/* --------------------------------------------------------- life cycle */

/* [thread-safe] Loads the plugins the config names, builds the pipeline of
 * the configured mount, loads the config's map. On failure *engine is NULL,
 * nothing is left loaded, and err names the problem (err.where is a JSON
 * pointer into the config, a plugin file, or "map:<pointer into the map>"). */
PN_API pn_status_t pn_engine_create(const pn_engine_create_info_t *info, pn_engine_t **engine,
                                    pn_error_t *err);
/* [exclusive] NULL-safe. Destroys instances, then unloads libraries. */
PN_API void pn_engine_destroy(pn_engine_t *engine);

/* ------------------------------------------------------------- inputs */

/* [producer] Push `count` IMU samples laid out `stride_bytes` apart (>= header.struct_size
 * of every sample; lets apps built against another minor index correctly: a
 * sample claiming more is refused with PN_E_INVALID_ARGUMENT, err.detail = its
 * index).
 * Samples are processed before the call returns, except those at the newest
 * time, which wait for a later sample or flush (see docs/scheduler.md). A
 * sample with a non-finite value or time not after the previous sample is
 * rejected: the call stops there and returns PN_E_NUMERIC / PN_E_OUT_OF_ORDER
 * with err.detail = its index; the samples before it are processed and kept.
 * A plugin failing while processing returns its status with err.where = the
 * instance ("foot/position_filter") and err.detail = the index of the sample
 * whose push triggered the processing (accepted: do not push it again). */
PN_API pn_status_t pn_engine_push_imu(pn_engine_t *engine, const pn_imu_t *samples, size_t count,
                                      size_t stride_bytes, pn_error_t *err);
/* [producer] Push one record of any input type (IMU, MAG, BARO, GNSS). Same
 * rules. A GNSS fix may give the engine its geodetic origin (see
 * pn_engine_set_origin). */
PN_API pn_status_t pn_engine_push(pn_engine_t *engine, const pn_record_header_t *record,
                                  pn_error_t *err);
/* [producer] Push `count` records of any input type, in the order given
 * (records[i] points at one record; what pn_engine_push does for each, in one
 * call: bindings push whole recordings without a call per sample). Stops at
 * the first record that fails with its status and err.detail = its index; the
 * records before it are processed (a plugin failure means that record was
 * accepted: continue from the next one, as after a rejected record). */
PN_API pn_status_t pn_engine_push_records(pn_engine_t *engine, const pn_record_header_t *const *records,
                                          size_t count, pn_error_t *err);
/* [producer] End of stream: drains the look-ahead of every stage. Pushing
 * after flush continues a new segment. */
PN_API pn_status_t pn_engine_flush(pn_engine_t *engine, pn_error_t *err);
/* [exclusive] Back to the state right after create: plugins reset, queues
 * and outputs emptied, counters kept. What the app set before its first push
 * (start, attitude, origin, map) and the config's map are given again to the
 * fresh plugins; an origin taken from a GNSS fix is forgotten. */
PN_API pn_status_t pn_engine_reset(pn_engine_t *engine, pn_error_t *err);

/* ------------------------------------------------- before the first push */

/* [producer] Start point (ENU m) and heading (deg clockwise from north, NaN =
 * from the sensors) handed to the position filter and map matcher. Only
 * before the first push (or after a reset): later, PN_E_BAD_STATE and nothing
 * changes. PN_E_UNSUPPORTED when no stage takes a start point. */
PN_API pn_status_t pn_engine_set_start(pn_engine_t *engine, const double pos_enu_m[3],
                                       double heading_deg, pn_error_t *err);
/* [producer] 1.1. Initial attitude (unit quaternion, Hamilton, w first, ENU
 * from body) handed to the attitude estimator instead of its own alignment.
 * Only before the first push (or after a reset): later, PN_E_BAD_STATE.
 * PN_E_UNSUPPORTED when the pipeline's attitude estimator does not take one;
 * PN_E_INVALID_ARGUMENT when q is not finite or not of unit norm. */
PN_API pn_status_t pn_engine_set_attitude(pn_engine_t *engine, const double q_enu_from_body[4],
                                          pn_error_t *err);
/* [producer] 1.1. The geodetic origin: the WGS-84 point at ENU (0, 0, 0), read
 * by every plugin (pnp_host_t.get_origin) and used by the *_geo functions
 * below. Without one from the app or the config ("origin"), the engine takes
 * the one a map matcher offers from its map, else the first GNSS fix whose
 * h_accuracy_m is within the config's origin.from_fix_max_h_accuracy_m
 * (default 10 m). Only before the first push and while the engine has no
 * origin from elsewhere (config, map): else PN_E_BAD_STATE naming where the
 * current one came from. PN_E_INVALID_ARGUMENT when out of range. */
PN_API pn_status_t pn_engine_set_origin(pn_engine_t *engine, const pn_geo_point_t *origin,
                                        pn_error_t *err);
/* [producer] 1.1. The current origin: PN_OK, or PN_NO_DATA when none yet. */
PN_API pn_status_t pn_engine_get_origin(const pn_engine_t *engine, pn_geo_point_t *origin);
/* [producer] 1.1. ENU metres to WGS-84 and back, through the origin (exact
 * ellipsoidal conversion, not a flat-earth approximation): PN_NO_DATA while
 * there is no origin. Lets an app show outputs in latitude, longitude and
 * height. */
PN_API pn_status_t pn_engine_geo_from_enu(const pn_engine_t *engine, const double pos_enu_m[3],
                                          pn_geo_point_t *out);
PN_API pn_status_t pn_engine_enu_from_geo(const pn_engine_t *engine, const pn_geo_point_t *point,
                                          double pos_enu_m[3]);

/* -------------------------------------------------------------- maps */

/* [producer] 1.1. Hands a map to the pipeline's map matcher, replacing the
 * one loaded before; at create or between pushes, applies from the next
 * record. format: "pednav.map/1" (GeoJSON, docs/maps.md) or what the map
 * matcher documents; bytes borrowed for the call (the engine keeps a copy to
 * give again after a reset). PN_E_UNSUPPORTED when the pipeline has no map
 * matcher or it takes no maps; a map the matcher refuses returns its status
 * (PN_E_BAD_INPUT, ...) with err.where = "map:" + a JSON pointer into the map
 * naming the feature at fault, and the previous map stays. */
PN_API pn_status_t pn_engine_load_map(pn_engine_t *engine, const char *format, const void *bytes,
                                      size_t size, pn_error_t *err);

/* ---------------------------------------------------------- settings */

/* [producer] 1.1. New params for one stage, by role ("position_filter") or
 * instance name ("foot/position_filter"): the whole "params" object as JSON
 * (params_len bytes, 0 = NUL-terminated). Checked against the plugin's params
 * schema like the config (PN_E_INVALID_CONFIG, err.where a JSON pointer
 * relative to the stage: "/params/window_s"); applies from the next record and
 * survives reset. PN_E_NOT_FOUND for a role the pipeline lacks;
 * PN_E_UNSUPPORTED when the plugin cannot change them live (the old values
 * stay). */
PN_API pn_status_t pn_engine_reconfigure(pn_engine_t *engine, const char *stage, const char *params_json,
                                         size_t params_len, pn_error_t *err);

/* ------------------------------------------------------------ outputs */

/* [consumer] Pops the oldest output record into *out: PN_OK, or PN_NO_DATA
 * when empty. */
PN_API pn_status_t pn_engine_poll(pn_engine_t *engine, pn_output_t *out);
/* [consumer] Pops up to `capacity` output records, oldest first, into
 * out[0 .. *count): PN_OK (also when none: *count = 0). Each slot holds one
 * record (header.type says which) of header.struct_size bytes. */
PN_API pn_status_t pn_engine_poll_many(pn_engine_t *engine, pn_output_t *out, size_t capacity, size_t *count);
/* [producer] Copies the newest output of the given type without popping
 * anything: PN_OK, or PN_NO_DATA if none yet. */
PN_API pn_status_t pn_engine_get_latest(pn_engine_t *engine, pn_record_type_t type,
                                        pn_output_t *out);
/* [any thread] Which record types reach the output queue (PN_REC_MASK bits of
 * POSITION, STRIDE, STEP, ATTITUDE, GAIT_PHASE, ATTITUDE_CORRECTION). By
 * default: POSITION, STRIDE, STEP (the floor is in POSITION). ATTITUDE and
 * GAIT_PHASE are per sample and off unless asked for. A bit of any other
 * type (inputs, unknown types) is refused with PN_E_INVALID_ARGUMENT and the
 * mask stays as it was. Takes effect for records emitted after the call. */
PN_API pn_status_t pn_engine_set_output_mask(pn_engine_t *engine, uint64_t mask);

/* [producer] Output latency of the pipeline in ns (sum of the stages'
 * look-ahead). */
PN_API int64_t pn_engine_latency_ns(const pn_engine_t *engine);

/* [producer] JSON description: engine version, loaded libraries and plugins,
 * rejected files with their reasons, the pipeline with its stages and latency,
 * the origin and map, counters (samples, dropped outputs, warnings), the
 * warnings. Writes up to `capacity` bytes including the NUL, sets *size to the
 * full size including the NUL. Returns PN_OK, or PN_E_INVALID_ARGUMENT if the
 * buffer was too small (call again with *size). */
PN_API pn_status_t pn_engine_describe(const pn_engine_t *engine, char *buffer, size_t capacity,
                                      size_t *size);

/* Flag of pn_plugins_describe: also open every library found. */
#define PN_LIST_OPEN_LIBRARIES 1u

/* [thread-safe] Describes the plugin libraries in the directories without a
 * config or an engine: JSON with the "libraries", "plugins", "rejected" and
 * "load_warnings" members of pn_engine_describe (docs/loading.md). flags 0
 * reads the manifests beside the libraries and opens nothing (a library
 * without a manifest is only named in "load_warnings");
 * PN_LIST_OPEN_LIBRARIES also opens every library (running its initializers,
 * never its init) to read its descriptors and report where a manifest and its
 * library disagree. Unknown flag bits are refused with PN_E_INVALID_ARGUMENT.
 * Two-call size idiom as pn_engine_describe: *size is set to the full size
 * including the NUL; PN_E_INVALID_ARGUMENT if `capacity` is too small. */
PN_API pn_status_t pn_plugins_describe(const char *const *plugin_dirs, uint32_t dir_count, uint32_t flags,
                                       char *buffer, size_t capacity, size_t *size, pn_error_t *err);

#ifdef __cplusplus
}
#endif

#endif /* PEDNAV_PN_ENGINE_H */
