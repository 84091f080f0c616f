#pragma once
// Small helpers for writing HTML by hand: escaping, URLs of relative paths, number formats.
#include <filesystem>
#include <string>
#include <string_view>

namespace cls {

// Text or attribute value: & < > " ' escaped.
std::string html_escape(std::string_view text);

// A relative path as a URL: '/'-separated, every byte outside [A-Za-z0-9-._~/] percent-encoded, so
// that a view named "a #1.png" still resolves.
std::string url_of(const std::filesystem::path& relative);

// `value` with `decimals` decimals ("-" for NaN or infinity).
std::string fixed(double value, int decimals);

// A duration for people: "0.4 s", "12 s", "3 min 05 s", "2 h 07 min".
std::string duration_text(double seconds);

}  // namespace cls
