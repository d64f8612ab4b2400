// Optimisation hints for the few hot loops that take them. GCC takes a function's own -O3 and
// "ivdep"; clang has neither (no per-function -O level; its vectoriser checks the loops'
// aliasing at run time), so they are empty there and elsewhere.
#pragma once

#if defined(__GNUC__) && !defined(__clang__)
#define TS_OPTIMIZE_O3 [[gnu::optimize("O3")]]
#define TS_LOOP_IVDEP _Pragma("GCC ivdep")
#else
#define TS_OPTIMIZE_O3
#define TS_LOOP_IVDEP
#endif
