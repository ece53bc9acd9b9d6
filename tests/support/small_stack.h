#pragma once
// Runs a body on a thread with a small stack: code that took a large native
// frame per tree level would overflow it on a legal tree (kMaxNodeDepth
// levels), as the recursive node reader did. Under AddressSanitizer every
// frame is larger (the JSON writer's recursion overflowed 1 MB at 1024
// levels there, and fits in release), so the stack is scaled there.

#include <pthread.h>

#include <cstddef>
#include <functional>

#include <gtest/gtest.h>

#include "support/sanitizers.h"

namespace sdfwb::test {

inline constexpr std::size_t kAddressSanitizerStackScale = 4;

inline void onSmallStack(std::size_t bytes, const std::function<void()>& body) {
    pthread_attr_t attributes;
    ASSERT_EQ(pthread_attr_init(&attributes), 0);
    ASSERT_EQ(pthread_attr_setstacksize(&attributes, kAddressSanitizer ? bytes * kAddressSanitizerStackScale : bytes), 0);
    pthread_t thread;
    auto run = [](void* f) -> void* {
        (*static_cast<const std::function<void()>*>(f))();
        return nullptr;
    };
    ASSERT_EQ(pthread_create(&thread, &attributes, run, const_cast<std::function<void()>*>(&body)), 0);
    pthread_join(thread, nullptr);
    pthread_attr_destroy(&attributes);
}

}  // namespace sdfwb::test
