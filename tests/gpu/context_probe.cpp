// Makes a gpu::Context and says which device it chose; on bad input, one line on stderr and
// exit 2, as the terrashade command does. The no-device test runs it without any driver.
#include <cstdio>
#include <exception>

#include "core/util/error.hpp"
#include "gpu/context.hpp"

int main() {
    try {
        const ts::gpu::Context context;
        std::printf("%s\n", context.device_info().name.c_str());
        return 0;
    } catch (const ts::InputError& e) {
        std::fprintf(stderr, "terrashade: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "terrashade: internal error: %s\n", e.what());
        return 1;
    }
}
