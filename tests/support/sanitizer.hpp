// Whether the tests are built with a sanitizer (scripts/build.sh check and
// tsan). GCC says __SANITIZE_ADDRESS__ / __SANITIZE_THREAD__, clang (before
// 17) only __has_feature(...).
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define SKIPNC_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SKIPNC_TEST_ASAN 1
#endif
#endif
#ifndef SKIPNC_TEST_ASAN
#define SKIPNC_TEST_ASAN 0
#endif

#if defined(__SANITIZE_THREAD__)
#define SKIPNC_TEST_TSAN 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define SKIPNC_TEST_TSAN 1
#endif
#endif
#ifndef SKIPNC_TEST_TSAN
#define SKIPNC_TEST_TSAN 0
#endif
