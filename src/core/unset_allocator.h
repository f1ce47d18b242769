// Private: an allocator whose vectors leave new elements of a trivial type
// unset (resize() does not zero what is written next anyway), so that the
// threads that write them first are the ones that fault their pages in: the
// readers' 2M-face corner arrays (24 MB), the surface distance's sample
// distances (160 MB for 20M samples), each zeroed serially before.
#pragma once

#include <memory>
#include <utility>

namespace meshdiff::detail {

template <class T>
struct UnsetAllocator : std::allocator<T>
{
    template <class U>
    struct rebind
    {
        using other = UnsetAllocator<U>;
    };
    UnsetAllocator() = default;
    template <class U>
    UnsetAllocator(const UnsetAllocator<U>&) noexcept
    {}
    //! Default-initialises: nothing written for a trivial type.
    template <class U>
    void construct(U* p) noexcept
    {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... A>
    void construct(U* p, A&&... a)
    {
        ::new (static_cast<void*>(p)) U(std::forward<A>(a)...);
    }
};

}  // namespace meshdiff::detail
