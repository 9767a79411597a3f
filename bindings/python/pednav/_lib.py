# SPDX-License-Identifier: Apache-2.0
"""The C API of libpednav (pn_engine.h, pn_io.h) through cffi in ABI mode.

Where things are: the environment variable PEDNAV_PREFIX names a pednav build
folder or install prefix (bin/pednav, lib/libpednav.so, lib/pednav/plugins,
share/pednav/configs); without it, the prefix this package was installed into
by `cmake --install` (recorded in _install.py). PEDNAV_LIBRARY, PEDNAV_PLUGIN_DIR,
PEDNAV_CONFIG_DIR and PEDNAV_CLI override single paths.
"""
import os

import cffi

CDEF = """
typedef int32_t pn_status_t;
typedef uint32_t pn_record_type_t;
typedef struct pn_error_t {
    uint32_t struct_size;
    pn_status_t code;
    int32_t detail;
    uint32_t reserved;
    char where[128];
    char message[256];
} pn_error_t;
typedef struct pn_geo_point_t { double lat_deg; double lon_deg; double height_m; } pn_geo_point_t;
typedef struct pn_record_header_t pn_record_header_t;
typedef struct pn_imu_t pn_imu_t;
typedef struct pn_position_t pn_position_t;
typedef struct pn_stride_t pn_stride_t;
typedef struct pnp_library_t pnp_library_t;
typedef void (*pn_log_fn)(void *user, int32_t level, const char *source, const char *msg);
typedef struct pn_engine_create_info_t {
    uint32_t abi_version;
    uint32_t struct_size;
    const char *config_json;
    size_t config_len;
    const char *const *plugin_dirs;
    uint32_t plugin_dir_count;
    uint32_t static_library_count;
    const pnp_library_t *const *static_libraries;
    pn_log_fn log;
    void *log_user;
    uint32_t output_queue_capacity;
    uint32_t reserved;
} pn_engine_create_info_t;
typedef struct pn_engine_t pn_engine_t;
typedef union pn_output_t { unsigned char bytes[512]; } pn_output_t;

uint32_t pn_abi_version(void);
const char *pn_version_string(void);
const char *pn_status_name(pn_status_t status);
pn_status_t pn_engine_create(const pn_engine_create_info_t *info, pn_engine_t **engine, pn_error_t *err);
void pn_engine_destroy(pn_engine_t *engine);
pn_status_t pn_engine_push_imu(pn_engine_t *engine, const pn_imu_t *samples, size_t count,
                               size_t stride_bytes, pn_error_t *err);
pn_status_t pn_engine_push(pn_engine_t *engine, const pn_record_header_t *record, pn_error_t *err);
pn_status_t pn_engine_push_records(pn_engine_t *engine, const pn_record_header_t *const *records,
                                   size_t count, pn_error_t *err);
pn_status_t pn_engine_flush(pn_engine_t *engine, pn_error_t *err);
pn_status_t pn_engine_reset(pn_engine_t *engine, pn_error_t *err);
pn_status_t pn_engine_set_start(pn_engine_t *engine, const double pos_enu_m[3], double heading_deg,
                                pn_error_t *err);
pn_status_t pn_engine_set_origin(pn_engine_t *engine, const pn_geo_point_t *origin, pn_error_t *err);
pn_status_t pn_engine_get_origin(const pn_engine_t *engine, pn_geo_point_t *origin);
pn_status_t pn_engine_geo_from_enu(const pn_engine_t *engine, const double pos_enu_m[3], pn_geo_point_t *out);
pn_status_t pn_engine_enu_from_geo(const pn_engine_t *engine, const pn_geo_point_t *point, double pos_enu_m[3]);
pn_status_t pn_engine_load_map(pn_engine_t *engine, const char *format, const void *bytes, size_t size,
                               pn_error_t *err);
pn_status_t pn_engine_reconfigure(pn_engine_t *engine, const char *stage, const char *params_json,
                                  size_t params_len, pn_error_t *err);
pn_status_t pn_engine_poll_many(pn_engine_t *engine, pn_output_t *out, size_t capacity, size_t *count);
pn_status_t pn_engine_set_output_mask(pn_engine_t *engine, uint64_t mask);
int64_t pn_engine_latency_ns(const pn_engine_t *engine);
pn_status_t pn_engine_describe(const pn_engine_t *engine, char *buffer, size_t capacity, size_t *size);

typedef struct pn_recording_t pn_recording_t;
typedef struct pn_truth_point_t pn_truth_point_t;
pn_status_t pn_recording_open(const char *path, const char *format, const char *options_json,
                              pn_recording_t **recording, pn_error_t *err);
void pn_recording_destroy(pn_recording_t *recording);
pn_status_t pn_recording_stream(const pn_recording_t *recording, pn_record_type_t type,
                                const void **records, size_t *count, size_t *stride_bytes);
pn_status_t pn_recording_merged(const pn_recording_t *recording, const pn_record_header_t *const **records,
                                size_t *count);
pn_status_t pn_recording_truth(const pn_recording_t *recording, const pn_truth_point_t **points,
                               size_t *count);
pn_status_t pn_recording_describe(const pn_recording_t *recording, char *buffer, size_t capacity,
                                  size_t *size);
pn_status_t pn_recording_formats(char *buffer, size_t capacity, size_t *size);
pn_status_t pn_write_track_csv(const char *path, const pn_position_t *positions, size_t count,
                               pn_error_t *err);
pn_status_t pn_write_steps_csv(const char *path, const pn_stride_t *strides, size_t count, pn_error_t *err);
"""

ABI_VERSION = (1 << 16) | 1  # PN_ABI_VERSION this binding was written against
OUTPUT_SLOT_BYTES = 512  # sizeof(pn_output_t)

ffi = cffi.FFI()
ffi.cdef(CDEF)


class PednavError(RuntimeError):
    """A failed C API call: status (e.g. "PN_E_INVALID_CONFIG"), code, where
    (JSON pointer, path:line, instance name), detail (a line or sample index),
    message."""

    def __init__(self, status, code, where, detail, message):
        self.status = status
        self.code = code
        self.where = where
        self.detail = detail
        self.message = message
        text = status
        if where:
            text += " at " + where
        if message:
            text += ": " + message
        super().__init__(text)


def _prefix():
    prefix = os.environ.get("PEDNAV_PREFIX")
    if prefix:
        return prefix
    try:
        from . import _install
    except ImportError:
        return None
    return os.path.normpath(os.path.join(os.path.dirname(__file__), _install.PREFIX_FROM_PACKAGE))


def _layout():
    try:
        from . import _install
        return _install.LIBDIR, _install.PLUGIN_DIR, _install.CONFIG_DIR, _install.BINDIR
    except ImportError:
        return "lib", "lib/pednav/plugins", "share/pednav/configs", "bin"


def path_of(what):
    """The path of "library", "plugins", "configs" or "cli"."""
    env = {"library": "PEDNAV_LIBRARY", "plugins": "PEDNAV_PLUGIN_DIR", "configs": "PEDNAV_CONFIG_DIR",
           "cli": "PEDNAV_CLI"}[what]
    if os.environ.get(env):
        return os.environ[env]
    prefix = _prefix()
    if prefix is None:
        raise RuntimeError("pednav: set PEDNAV_PREFIX to a pednav build folder or install prefix "
                           "(or install the package with cmake --install), or set " + env)
    libdir, plugin_dir, config_dir, bindir = _layout()
    rel = {"library": os.path.join(libdir, "libpednav.so"), "plugins": plugin_dir, "configs": config_dir,
           "cli": os.path.join(bindir, "pednav")}[what]
    return os.path.join(prefix, rel)


_lib = None


def lib():
    """The loaded libpednav, checked for the ABI major this binding speaks."""
    global _lib
    if _lib is None:
        path = path_of("library")
        if not os.path.exists(path):
            raise RuntimeError("pednav: no libpednav at " + path + " (PEDNAV_PREFIX or PEDNAV_LIBRARY)")
        loaded = ffi.dlopen(path)
        if loaded.pn_abi_version() >> 16 != ABI_VERSION >> 16:
            raise RuntimeError("pednav: %s speaks ABI %#x, this package %#x" %
                               (path, loaded.pn_abi_version(), ABI_VERSION))
        _lib = loaded
    return _lib


def new_error():
    err = ffi.new("pn_error_t *")
    err.struct_size = ffi.sizeof("pn_error_t")
    return err


def raise_error(status, err):
    """Raises PednavError for a failed status with what err says."""
    name = ffi.string(lib().pn_status_name(status)).decode()
    raise PednavError(name, int(status), ffi.string(err.where).decode(errors="replace"), int(err.detail),
                      ffi.string(err.message).decode(errors="replace"))


def check(status, err, allow=()):
    if status < 0 and status not in allow:
        raise_error(status, err)
    return status


def sized_text(call):
    """Text of a two-call size idiom function: call(buffer, capacity, size_ptr)."""
    size = ffi.new("size_t *")
    call(ffi.NULL, 0, size)
    buf = ffi.new("char[]", max(1, size[0]))
    status = call(buf, size[0], size)
    if status != 0:
        raise PednavError(ffi.string(lib().pn_status_name(status)).decode(), int(status), "", 0,
                          "could not get the text")
    return ffi.string(buf).decode()
