// SPDX-License-Identifier: GPL-3.0-or-later
// FT_UNDER_ASAN is defined when the test is built with AddressSanitizer
// (gcc's __SANITIZE_ADDRESS__ or clang's __has_feature), for the tests that
// limit the address space, which ASan's shadow memory cannot live with.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define FT_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FT_UNDER_ASAN 1
#endif
#endif
