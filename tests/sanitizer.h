// SCALLOP_UNDER_ASAN: 1 when the product the tests run is built with AddressSanitizer.
// The sanitizer build says so itself (tests/CMakeLists.txt: the test files are compiled
// without instrumentation there, so the compiler's own signs are absent); otherwise GCC
// defines __SANITIZE_ADDRESS__ and clang reports it through __has_feature.
// Tests that measure memory use skip themselves there: redzones, shadow memory and
// the quarantine of freed blocks change every figure.
#pragma once

#ifndef SCALLOP_UNDER_ASAN
#if defined(__SANITIZE_ADDRESS__)
#define SCALLOP_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SCALLOP_UNDER_ASAN 1
#endif
#endif
#endif
#ifndef SCALLOP_UNDER_ASAN
#define SCALLOP_UNDER_ASAN 0
#endif
