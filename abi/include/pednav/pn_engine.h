/*
 * pednav stable C ABI, part 3 of 3: the app-facing engine API.
 *
 * An app creates an engine from a JSON config and a list of plugin
 * directories, pushes sensor samples, and polls outputs. Processing runs
 * inside the push calls on the caller's thread, so the same input and config
 * give bit-identical output (replays of field recordings reproduce bugs).
 *
 * Threading: calls on one engine are not synchronized, except that one thread
 * may push while one other thread polls (single-producer, single-consumer
 * output queue). Different engines are independent.
 *
 * Every function accepts err == NULL. No function returns memory the caller
 * must free; text goes into caller buffers with the two-call size idiom.
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

#if defined(_WIN32)
#define PN_API __declspec(dllexport)
#else
#define PN_API __attribute__((visibility("default")))
#endif

typedef struct pn_engine_t pn_engine_t; /* opaque */

/* Log callback: [thread-safe on the app side]; msg borrowed for the call.
 * `source` is "engine" or an instance name such as "foot/position_filter". */
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
    uint32_t output_queue_capacity; /* records kept until polled; 0 = 8192. When full, new
                                       outputs are dropped and counted in describe
                                       (counters.outputs_dropped); get_latest still sees them. */
    uint32_t reserved;
} pn_engine_create_info_t;

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

/* Version of the library and its ABI. [thread-safe] */
PN_API uint32_t pn_abi_version(void);
PN_API const char *pn_version_string(void);
/* Name of a status code ("PN_E_INVALID_CONFIG"); never NULL. [thread-safe] */
PN_API const char *pn_status_name(pn_status_t status);

/* Loads the plugins the config names, builds the pipeline of the configured
 * mount. On failure *engine is NULL and err names the problem (err.where is a
 * JSON pointer into the config, or a plugin file). */
PN_API pn_status_t pn_engine_create(const pn_engine_create_info_t *info, pn_engine_t **engine,
                                    pn_error_t *err);
/* NULL-safe. Destroys instances, then unloads libraries. */
PN_API void pn_engine_destroy(pn_engine_t *engine);

/* Push `count` IMU samples laid out `stride_bytes` apart (>= header.struct_size
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
/* Push one record of any input type (IMU, MAG, BARO, GNSS). Same rules. */
PN_API pn_status_t pn_engine_push(pn_engine_t *engine, const pn_record_header_t *record,
                                  pn_error_t *err);
/* End of stream: drains the look-ahead of every stage. Pushing after flush
 * continues a new segment. */
PN_API pn_status_t pn_engine_flush(pn_engine_t *engine, pn_error_t *err);
/* Back to the state right after create (plugins reset, queues emptied). */
PN_API pn_status_t pn_engine_reset(pn_engine_t *engine, pn_error_t *err);
/* Start point (ENU m) and heading (deg clockwise from north, NaN = from the
 * sensors) handed to the position filter and map matcher. Call before the
 * first push. */
PN_API pn_status_t pn_engine_set_start(pn_engine_t *engine, const double pos_enu_m[3],
                                       double heading_deg, pn_error_t *err);

/* Pops the oldest output record into *out: PN_OK, or PN_NO_DATA when empty. */
PN_API pn_status_t pn_engine_poll(pn_engine_t *engine, pn_output_t *out);
/* Copies the newest output of the given type without popping anything:
 * PN_OK, or PN_NO_DATA if none yet. Call from the pushing thread. */
PN_API pn_status_t pn_engine_get_latest(pn_engine_t *engine, pn_record_type_t type,
                                        pn_output_t *out);
/* Which record types reach the output queue (PN_REC_MASK bits). By default:
 * POSITION, STRIDE, STEP and the floor (in POSITION). ATTITUDE and GAIT_PHASE
 * are per sample and off unless asked for. */
PN_API pn_status_t pn_engine_set_output_mask(pn_engine_t *engine, uint64_t mask);

/* Output latency of the pipeline in ns (sum of the stages' look-ahead). */
PN_API int64_t pn_engine_latency_ns(const pn_engine_t *engine);

/* JSON description: engine version, loaded libraries and plugins, rejected
 * files with their reasons, the pipeline with its stages and latency,
 * counters (samples, dropped outputs, warnings). Writes up to `capacity`
 * bytes including the NUL, sets *size to the full size including the NUL.
 * Returns PN_OK, or PN_E_INVALID_ARGUMENT if the buffer was too small (call
 * again with *size). */
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
