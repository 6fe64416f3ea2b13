#pragma once
// Base64 (RFC 4648, with padding) of binary data, for pages that embed arrays as text a script decodes into
// a typed array (the HTML report of ochre-regress, the relighting page of ochre relight): no second file
// to fetch, which a page opened from a file:// URL may not.

#include <cstddef>
#include <string>
#include <vector>

namespace ochre {

std::string base64(const unsigned char* bytes, size_t count);

// The floats as little-endian IEEE 754 binary32.
std::string base64_floats(const std::vector<float>& values);

}  // namespace ochre
