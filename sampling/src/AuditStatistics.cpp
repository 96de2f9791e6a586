#include <sampling/AuditStatistics.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sdfwb::sampling {

float percentile(std::vector<float> values, double q) {
    if (values.empty()) return 0.0f;
    std::size_t k = std::min(values.size() - 1, std::size_t(q * double(values.size() - 1) + 0.5));
    std::nth_element(values.begin(), values.begin() + long(k), values.end());
    return values[k];
}

float quadraticResidualStep(const float* f, int count) {
    // Least squares on x symmetric about 0, so the linear term decouples: the constant and the
    // quadratic from their 2x2 normal equations, the slope on its own.
    double sx2 = 0, sx4 = 0, s0 = 0, s1 = 0, s2 = 0;
    for (int k = 0; k < count; ++k) {
        if (!std::isfinite(f[k])) return std::numeric_limits<float>::quiet_NaN();
        const double x = k - (count - 1) / 2.0;
        sx2 += x * x;
        sx4 += x * x * x * x;
        s0 += f[k];
        s1 += x * f[k];
        s2 += x * x * f[k];
    }
    const double det = count * sx4 - sx2 * sx2;
    const double a = (s0 * sx4 - s2 * sx2) / det, c = (count * s2 - sx2 * s0) / det, b = s1 / sx2;
    double residual = 0;
    for (int k = 0; k < count; ++k) {
        const double x = k - (count - 1) / 2.0;
        const double e = f[k] - (a + b * x + c * x * x);
        residual += e * e;
    }
    return float(std::sqrt(12.0 * residual / (count - 3)));
}

std::pair<float, int> largestStep(const float* f, int count) {
    std::vector<float> differences;
    int at = 0;
    for (int k = 0; k + 1 < count; ++k) {
        if (!std::isfinite(f[k]) || !std::isfinite(f[k + 1])) return {-1.0f, 0};
        differences.push_back(std::abs(f[k + 1] - f[k]));
        if (differences.back() > differences[std::size_t(at)]) at = k;
    }
    if (differences.empty()) return {-1.0f, 0};
    const float largest = differences[std::size_t(at)];
    return {largest - percentile(differences, 0.5), at};
}

int plateauStart(const float* f, const float* distances, int count, float noise) {
    const int last = count - 1;
    if (count < 3 || !std::isfinite(f[last]) || f[last] <= 0.0f) return -1;
    // Walk back from the far end while the profile stays flat, step by step and to the end.
    int first = last;
    while (first > 0) {
        const float previous = f[first - 1];
        if (!std::isfinite(previous)) break;
        if (std::abs(previous - f[first]) > 0.02f * (distances[first] - distances[first - 1]) + noise) break;
        if (std::abs(previous - f[last]) > 0.02f * (distances[last] - distances[first - 1]) + noise) break;
        --first;
    }
    const float reach = distances[last] - distances[0];
    if (first > last - 2 || distances[last] - distances[first] < 0.1f * reach || f[first] <= 0.0f) return -1;
    return first;
}

} // namespace sdfwb::sampling
