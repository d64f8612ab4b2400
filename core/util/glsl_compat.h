// The macros that let one formula file compile as C++ (double) and as GLSL (float):
// core/sh/sh_shared.h and core/visibility/sky_shared.h are written against them.
// GLSL: `#define TS_GLSL 1` before including. C++: include through the .hpp wrapper of each
// shared file, which opens a namespace and brings std::sin & co. into it.
#ifndef TS_GLSL_COMPAT_H
#define TS_GLSL_COMPAT_H

#ifdef TS_GLSL
#define TS_REAL float
#define TS_VEC3 vec3
#define TS_OUT_ARRAY(T, name, N) out T name[N]
#define TS_INOUT_ARRAY(T, name, N) inout T name[N]
#define TS_IN_ARRAY(T, name, N) in T name[N]
#define TS_INLINE
#else
#define TS_REAL double
#define TS_VEC3 glm::dvec3
#define TS_OUT_ARRAY(T, name, N) T(&name)[N]
#define TS_INOUT_ARRAY(T, name, N) T(&name)[N]
#define TS_IN_ARRAY(T, name, N) const T(&name)[N]
#define TS_INLINE inline
#endif

#define TS_PI 3.14159265358979323846

#endif  // TS_GLSL_COMPAT_H
