/* SPDX-License-Identifier: Apache-2.0 */
/*
 * From C, as an app would: set the geodetic origin, load a GeoJSON map, and
 * see that the map matcher read both (org.pednav.test.map_anchor moves every
 * position to the map's first Point, in ENU metres around the origin, and
 * reports the number of features as the floor). Then: a broken map is refused
 * naming the feature at fault and the previous map stays; the map and origin
 * survive a reset; a map's own origin is taken when the app gives none; a good
 * GNSS fix gives the origin when nothing else did.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <pednav/pn_engine.h>

static int failures = 0;
#define CHECK(cond)                                                        \
    do {                                                                   \
        if (!(cond)) {                                                     \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
            ++failures;                                                    \
        }                                                                  \
    } while (0)

static const char *const kDirs[] = {PEDNAV_TEST_PLUGIN_DIR "/good", PEDNAV_TEST_PLUGIN_DIR "/map_anchor"};

static const char *const kConfig =
    "{\"format\": \"pednav-config/1\", \"mount\": \"foot\", \"pipelines\": {\"foot\": {"
    "\"step_detector\": {\"plugin\": \"org.pednav.test.counting_steps\"},"
    "\"position_filter\": {\"plugin\": \"org.pednav.test.step_counter\"},"
    "\"map_matcher\": {\"plugin\": \"org.pednav.test.map_anchor\"}}}}";

/* Origin 48.1 N 11.5 E 500 m; a Point 10 m north of it (1 deg of latitude is
 * 111 200.99 m at 48.1 N, 500 m up, on WGS-84: meridian radius 6 370 847.6 m). */
static const pn_geo_point_t kOrigin = {48.1, 11.5, 500.0};
#define NORTH_10M_DEG (10.0 / 111200.994)

static pn_engine_t *create(const char *config) {
    pn_engine_create_info_t info;
    pn_error_t err;
    pn_engine_t *e = NULL;
    memset(&info, 0, sizeof info);
    memset(&err, 0, sizeof err);
    err.struct_size = sizeof err;
    info.abi_version = PN_ABI_VERSION;
    info.struct_size = sizeof info;
    info.config_json = config;
    info.plugin_dirs = kDirs;
    info.plugin_dir_count = 2;
    if (pn_engine_create(&info, &e, &err) != PN_OK) fprintf(stderr, "create: %s: %s\n", err.where, err.message);
    return e;
}

static pn_status_t push_walk(pn_engine_t *e, int first, int count) {
    int k;
    for (k = first; k < first + count; ++k) {
        pn_imu_t s;
        pn_status_t st;
        memset(&s, 0, sizeof s);
        s.header.struct_size = sizeof s;
        s.header.type = PN_REC_IMU;
        s.header.t_ns = 1000000000LL + (int64_t)k * 10000000LL;
        s.accel_mps2[2] = 9.81;
        st = pn_engine_push_imu(e, &s, 1, sizeof s, NULL);
        if (st != PN_OK) return st;
    }
    return pn_engine_flush(e, NULL);
}

/* The last position polled; its count in *n. */
static pn_position_t last_position(pn_engine_t *e, int *n) {
    pn_output_t o;
    pn_position_t last;
    memset(&last, 0, sizeof last);
    *n = 0;
    while (pn_engine_poll(e, &o) == PN_OK)
        if (o.header.type == PN_REC_POSITION) {
            last = o.position;
            ++*n;
        }
    return last;
}

static void map_with_point(char *buf, size_t size, double lat_deg, const char *extra) {
    snprintf(buf, size,
             "{\"type\": \"FeatureCollection\"%s, \"features\": ["
             "{\"type\": \"Feature\", \"geometry\": {\"type\": \"Point\", \"coordinates\": [11.5, %.10f, 501.5]}},"
             "{\"type\": \"Feature\", \"geometry\": {\"type\": \"LineString\", \"coordinates\": [[11.5, 48.1], [11.5001, 48.1]]}}]}",
             extra, lat_deg);
}

static void test_app_origin_and_map(void) {
    char map[1024];
    const char *broken =
        "{\"type\": \"FeatureCollection\", \"features\": ["
        "{\"type\": \"Feature\", \"geometry\": {\"type\": \"Point\", \"coordinates\": [11.5, 48.1]}},"
        "{\"type\": \"Feature\", \"geometry\": {\"type\": \"LineString\", \"coordinates\": [[11.5, 48.1], [11.5, \"x\"]]}}]}";
    pn_error_t err;
    pn_geo_point_t o, g;
    pn_position_t p;
    const double up10[3] = {0.0, 10.0, 1.5};
    int n = 0;
    pn_engine_t *e = create(kConfig);
    CHECK(e != NULL);
    if (!e) return;
    memset(&err, 0, sizeof err);
    err.struct_size = sizeof err;

    CHECK(pn_engine_get_origin(e, &o) == PN_NO_DATA);
    CHECK(pn_engine_set_origin(e, &kOrigin, &err) == PN_OK);
    CHECK(pn_engine_get_origin(e, &o) == PN_OK && o.lat_deg == 48.1 && o.lon_deg == 11.5 && o.height_m == 500.0);
    map_with_point(map, sizeof map, 48.1 + NORTH_10M_DEG, "");
    CHECK(pn_engine_load_map(e, "pednav.map/1", map, strlen(map), &err) == PN_OK);

    /* A broken map: refused, naming the feature; the good map stays. */
    CHECK(pn_engine_load_map(e, "pednav.map/1", broken, strlen(broken), &err) == PN_E_BAD_INPUT);
    CHECK(strcmp(err.where, "map:/features/1/geometry/coordinates/1") == 0);
    CHECK(strstr(err.message, "foot/map_matcher refused the pednav.map/1 map: a coordinate must be a number") != NULL);

    CHECK(push_walk(e, 0, 50) == PN_OK);
    p = last_position(e, &n);
    CHECK(n == 5); /* a step every 10 samples */
    CHECK(fabs(p.pos_enu_m[0]) < 1e-6);
    CHECK(fabs(p.pos_enu_m[1] - 10.0) < 0.01);
    CHECK(fabs(p.pos_enu_m[2] - 1.5) < 1e-4); /* 1.5 m up, less the curvature over 10 m (8 um) */
    CHECK((p.header.flags & PN_POSITION_FLAG_HAS_FLOOR) && p.floor == 2);

    /* ENU to WGS-84 and back through the origin. */
    CHECK(pn_engine_geo_from_enu(e, up10, &g) == PN_OK);
    CHECK(fabs(g.lat_deg - (48.1 + NORTH_10M_DEG)) < 1e-8 && fabs(g.lon_deg - 11.5) < 1e-12);
    CHECK(fabs(g.height_m - 501.5) < 1e-5);

    /* Too late for an origin now; a reset keeps the app's origin and map. */
    CHECK(pn_engine_set_origin(e, &kOrigin, &err) == PN_E_BAD_STATE);
    CHECK(pn_engine_reset(e, &err) == PN_OK);
    CHECK(pn_engine_get_origin(e, &o) == PN_OK && o.lat_deg == 48.1);
    CHECK(push_walk(e, 0, 20) == PN_OK);
    p = last_position(e, &n);
    CHECK(n == 2 && fabs(p.pos_enu_m[1] - 10.0) < 0.01 && p.floor == 2);
    pn_engine_destroy(e);
}

static void test_map_origin_and_fix_origin(void) {
    char map[1024];
    pn_error_t err;
    pn_geo_point_t o;
    pn_gnss_t fix;
    pn_engine_t *e = create(kConfig);
    CHECK(e != NULL);
    if (!e) return;
    memset(&err, 0, sizeof err);
    err.struct_size = sizeof err;

    /* Without an origin the map's own is offered and taken. */
    map_with_point(map, sizeof map, 48.2, ", \"pednav:origin\": [11.5, 48.2, 480.0]");
    CHECK(pn_engine_load_map(e, "pednav.map/1", map, strlen(map), &err) == PN_OK);
    CHECK(pn_engine_get_origin(e, &o) == PN_OK && o.lat_deg == 48.2 && o.height_m == 480.0);
    CHECK(pn_engine_set_origin(e, &kOrigin, &err) == PN_E_BAD_STATE);
    CHECK(strstr(err.message, "from a plugin (foot/map_matcher)") != NULL);
    pn_engine_destroy(e);

    /* Without app, config or map, the first fix within 10 m becomes the origin. */
    e = create(kConfig);
    CHECK(e != NULL);
    if (!e) return;
    memset(&fix, 0, sizeof fix);
    fix.header.struct_size = sizeof fix;
    fix.header.type = PN_REC_GNSS;
    fix.header.t_ns = 1000000000LL;
    fix.lat_deg = 40.0;
    fix.lon_deg = -3.7;
    fix.height_m = 650.0;
    fix.h_accuracy_m = 25.0; /* too coarse */
    fix.v_accuracy_m = 30.0;
    CHECK(pn_engine_push(e, &fix.header, &err) == PN_OK);
    CHECK(pn_engine_get_origin(e, &o) == PN_NO_DATA);
    fix.header.t_ns += 1000000000LL;
    fix.lat_deg = 40.001;
    fix.h_accuracy_m = 4.0;
    CHECK(pn_engine_push(e, &fix.header, &err) == PN_OK);
    CHECK(pn_engine_get_origin(e, &o) == PN_OK && o.lat_deg == 40.001 && o.lon_deg == -3.7);
    /* A reset forgets an origin the data gave. */
    CHECK(pn_engine_reset(e, &err) == PN_OK);
    CHECK(pn_engine_get_origin(e, &o) == PN_NO_DATA);
    pn_engine_destroy(e);
}

int main(void) {
    test_app_origin_and_map();
    test_map_origin_and_fix_origin();
    if (failures) fprintf(stderr, "%d checks failed\n", failures);
    else printf("map and origin through the C API: all checks passed\n");
    return failures ? 1 : 0;
}
