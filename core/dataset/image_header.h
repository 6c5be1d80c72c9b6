// SPDX-License-Identifier: MIT
#pragma once

#include <opencv2/core.hpp>

#include <filesystem>
#include <optional>
#include <string_view>

namespace layermod {

// Images larger than this are refused before decoding (a header can declare any size; OpenCV
// would allocate up to gigabytes for it). 64 Mpx is far beyond any RGB-D sensor.
inline constexpr long long kMaxImagePixels = 64LL << 20;

// The width and height a PNG or JPEG declares in its header, read without decoding; nullopt for
// other formats or a header too short to tell (the decoder then decides).
std::optional<cv::Size> DeclaredImageSize(std::string_view bytes);

// Throws FormatError naming `path` when the declared size exceeds kMaxImagePixels or, when
// `expected` is given, differs from it ("image is WxH but <what> says WxH").
void CheckDeclaredImageSize(const std::filesystem::path& path, std::string_view bytes,
                            std::optional<cv::Size> expected, std::string_view what);

// Decodes an image file already read into memory (cv::imdecode flags); empty when OpenCV cannot.
// Callers check the declared size first and choose their own message for an empty result.
cv::Mat DecodeImageBytes(std::string_view bytes, int flags);

}  // namespace layermod
