// Small text helpers shared by the report's writers: CSV fields, HTML escaping, figures, atomic writes.
#pragma once

#include <string>

namespace viz::report {

// A CSV field, quoted (with doubled quotes) when it holds a comma, quote or newline.
std::string csvField(const std::string& text);
// Text safe inside HTML elements and attribute values.
std::string escapeHtml(const std::string& text);
// printf-formatted figure; empty for NaN and Inf (undefined figures print as nothing).
std::string formatFigure(double value, const char* format = "%.6g");

// A time ratio (baseline time / technique time) in words: "5.9x faster", "5.9x slower" (never
// "0.17x faster"), "as fast" within 1 %; "-" when the ratio is not a positive finite number.
std::string speedupPhrase(double ratio);
// A range of speed-ups in words: "between 4.90x and 6.51x faster", "between 1.25x and 2.00x slower",
// "between 1.20x slower and 1.30x faster"; the ends in either order.
std::string speedupRangePhrase(double a, double b);
// A work ratio (baseline work / technique work) in words: "12x less work", "1.50x more work", "as much
// work" within 1 %; "-" when the ratio is not a positive finite number.
std::string workRatioPhrase(double ratio);
// Writes the whole file atomically; throws InputError naming the path on failure.
void writeTextFile(const std::string& path, const std::string& text);

}  // namespace viz::report
