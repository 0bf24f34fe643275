#pragma once
// kSanitized: true under AddressSanitizer (about 10x slower), where the heavier tests
// shrink their inputs to stay within the suite's time.
namespace dualhex::testing {

inline constexpr bool kSanitized =
#if defined(__SANITIZE_ADDRESS__)
    true;
#else
    false;
#endif

}  // namespace dualhex::testing
