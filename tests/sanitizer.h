// SCALLOP_UNDER_ASAN: 1 when the tests are built with AddressSanitizer, by GCC (which
// defines __SANITIZE_ADDRESS__) or by clang (which reports it through __has_feature).
// Tests that measure memory use skip themselves there: redzones, shadow memory and
// the quarantine of freed blocks change every figure.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define SCALLOP_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SCALLOP_UNDER_ASAN 1
#endif
#endif
#ifndef SCALLOP_UNDER_ASAN
#define SCALLOP_UNDER_ASAN 0
#endif
