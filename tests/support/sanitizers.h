#pragma once
// Whether this build runs under AddressSanitizer (.ci/sanitize asan, the fuzz
// build), for the few tests whose setting it changes: its redzones make
// every stack frame larger, and its shadow memory needs terabytes of address
// space, so a process under `ulimit -v` cannot start.

namespace sdfwb::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif
#else
inline constexpr bool kAddressSanitizer = false;
#endif

}  // namespace sdfwb::test
