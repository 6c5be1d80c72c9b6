// SPDX-License-Identifier: MIT
// The exception family lives in the public API (<layermod/error.h>) so that the core's errors
// and the API's are the same types.
#pragma once

#include <layermod/error.h>
