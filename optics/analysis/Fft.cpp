#include "analysis/Fft.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "prescription/Pi.h"

namespace lenslab {

namespace {

// exp(sign 2 pi i k / n) for k < n / 2, computed directly (no recurrence: no drift over long rows).
std::vector<Complex> twiddles(std::size_t n, int sign) {
    std::vector<Complex> w(n / 2);
    for (std::size_t k = 0; k < n / 2; ++k) w[k] = std::polar(1.0, sign * 2 * kPi * double(k) / double(n));
    return w;
}

void transform(Complex* x, std::size_t n, const std::vector<Complex>& w) {
    for (std::size_t i = 1, j = 0; i < n; ++i) {  // bit-reversal permutation
        std::size_t bit = n >> 1;
        for (; j & bit; bit >>= 1) j ^= bit;
        j ^= bit;
        if (i < j) std::swap(x[i], x[j]);
    }
    for (std::size_t len = 2; len <= n; len <<= 1) {
        const std::size_t half = len / 2, stride = n / len;
        for (std::size_t start = 0; start < n; start += len)
            for (std::size_t k = 0; k < half; ++k) {
                const Complex a = x[start + k], b = x[start + k + half] * w[k * stride];
                x[start + k] = a + b;
                x[start + k + half] = a - b;
            }
    }
}

void requirePowerOfTwo(std::size_t n) {
    if (!isPowerOfTwo(n)) throw std::invalid_argument("fft: the length must be a power of two");
}

}  // namespace

bool isPowerOfTwo(std::size_t n) { return n > 0 && (n & (n - 1)) == 0; }

std::size_t nextPowerOfTwo(std::size_t n) {
    std::size_t p = 1;
    while (p < n) p <<= 1;
    return p;
}

void fft(std::vector<Complex>& data, int sign) {
    requirePowerOfTwo(data.size());
    transform(data.data(), data.size(), twiddles(data.size(), sign));
}

void fft2d(std::vector<Complex>& grid, std::size_t n, int sign) {
    requirePowerOfTwo(n);
    if (grid.size() != n * n) throw std::invalid_argument("fft2d: the grid must hold n x n values");
    const std::vector<Complex> w = twiddles(n, sign);
    for (std::size_t row = 0; row < n; ++row) transform(grid.data() + row * n, n, w);
    std::vector<Complex> column(n);
    for (std::size_t col = 0; col < n; ++col) {
        for (std::size_t row = 0; row < n; ++row) column[row] = grid[row * n + col];
        transform(column.data(), n, w);
        for (std::size_t row = 0; row < n; ++row) grid[row * n + col] = column[row];
    }
}

}  // namespace lenslab
