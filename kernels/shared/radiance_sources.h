// The radiance sources a caching method's hemisphere rays can read "the radiance beyond the first
// bounce" from (kernels/caching/radiance_source.h; host/methods/radiance_source.h). The program
// holding the rays' kernel is built with -DRC_RADIANCE_SOURCE=<one of these>.
#pragma once

#define RC_RADIANCE_PATH 0     // path-traced continuation
#define RC_RADIANCE_RECORDS 1  // a deeper cache level of irradiance records
#define RC_RADIANCE_GRID 2     // the irradiance vector grid
