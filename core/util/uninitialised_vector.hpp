#pragma once
// A std::vector whose resize() leaves new elements default-initialised (for float: not
// written), for large outputs that the code fills completely right after: a value-initialising
// std::vector<float> of the 185 MB horizon planes of a whole SRTM tile is a single-threaded
// memset plus every page fault on the calling thread, before any work starts;
// left unwritten, the pages are first touched by the workers that fill them.
// assign(n, value) and vector(n, value) still write `value`.
#include <memory>
#include <utility>
#include <vector>

namespace ts {

template <class T>
struct DefaultInitAllocator : std::allocator<T> {
    using value_type = T;
    template <class U>
    struct rebind {
        using other = DefaultInitAllocator<U>;
    };
    DefaultInitAllocator() = default;
    template <class U>
    DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}
    template <class U>
    void construct(U* p) {
        ::new (static_cast<void*>(p)) U;  // default-initialisation: trivial types stay unwritten
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

template <class T>
using UninitialisedVector = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace ts
