// CRC-32C (Castagnoli), the checksum of .finbook sections from format version 2 on (private
// to the model). It catches every burst of up to 32 flipped bits and all odd numbers of bit
// flips; the SSE4.2 instruction computes it at memory speed where the processor has one.
#pragma once

#include <cstddef>
#include <cstdint>

namespace finbook::model::io {

// Continues `crc` (0 to start) over `size` bytes at `data`.
std::uint32_t crc32c(std::uint32_t crc, const void *data, std::size_t size);

} // namespace finbook::model::io
