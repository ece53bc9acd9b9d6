#pragma once
// Runs a body on a thread with a small stack: code that took a native frame
// per tree level would overflow it on a legal tree (kMaxNodeDepth levels), as
// the recursive node reader did under AddressSanitizer, whose frames are larger.

#include <pthread.h>

#include <cstddef>
#include <functional>

#include <gtest/gtest.h>

namespace sdfwb::test {

inline void onSmallStack(std::size_t bytes, const std::function<void()>& body) {
    pthread_attr_t attributes;
    ASSERT_EQ(pthread_attr_init(&attributes), 0);
    ASSERT_EQ(pthread_attr_setstacksize(&attributes, bytes), 0);
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
