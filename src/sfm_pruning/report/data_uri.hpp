// Base64 data URIs, so the report embeds its pictures and needs no file beside it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace sfm_pruning {

// RFC 4648 base64 with padding.
std::string Base64Encode(const std::vector<uint8_t>& bytes);

// "data:<mime>;base64,<...>".
std::string DataUri(const std::string& mime, const std::vector<uint8_t>& bytes);

}  // namespace sfm_pruning
