// Shared by the libFuzzer targets: the input as text, with a size cap so that one execution
// stays in the milliseconds (the readers' own limits are tested by tests/cli).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace locus::fuzz {

inline constexpr std::size_t kMaxInputBytes = 4096;

inline std::optional<std::string_view> input_text(const std::uint8_t* data, std::size_t size) {
    if (size > kMaxInputBytes) {
        return std::nullopt;
    }
    return std::string_view(reinterpret_cast<const char*>(data), size);
}

// A failed property: abort, which libFuzzer reports as a crash with the input saved.
[[noreturn]] void property_failed(const char* what, std::string_view input);

}  // namespace locus::fuzz
