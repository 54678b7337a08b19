// SPDX-License-Identifier: GPL-2.0-only OR BSD-2-Clause
/*
 * ssp-v5-echo: examples/cookbook-rpmsg-echo/echo.c, word for word, with the
 * resource tables of this folder (fw.mk puts them first): firmware as the
 * support package's releases for TI's 4.x kernels made it.
 */
#include "../examples/cookbook-rpmsg-echo/echo.c"
