// The translation unit that builds the tests' shared precompiled header (ts_test_pch in
// tests/CMakeLists.txt); it defines nothing.
