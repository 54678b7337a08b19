// SPDX-License-Identifier: GPL-2.0-only
/*
 * sim/prusim_core.c, compiled unchanged into the prusim KUnit suite (its own
 * object here, so that it is not shared with another module's).
 */
#include "../../../sim/prusim_core.c"
