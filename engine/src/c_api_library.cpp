// SPDX-License-Identifier: Apache-2.0
// libpednav.so: the pn_engine.h API. The definitions live in c_api.cpp inside
// pednav_core, linked in whole; only the PN_API functions are visible.
#include <pednav/pn_engine.h>
