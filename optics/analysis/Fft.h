#pragma once
// A radix-2 fast Fourier transform (iterative Cooley-Tukey, in place), in one and two dimensions.
// Written here rather than taken from FFTW: the analysis transforms grids of 64 to 512 points, where
// a library buys no measurable time, and FFTW's GPL would bind the whole program.
#include <complex>
#include <cstddef>
#include <vector>

namespace lenslab {

using Complex = std::complex<double>;

bool isPowerOfTwo(std::size_t n);
std::size_t nextPowerOfTwo(std::size_t n);

// sum_n x_n exp(sign 2 pi i n k / N) for every k, N = data.size() a power of two; sign -1 is the
// forward transform, +1 the inverse without the 1/N. Throws std::invalid_argument otherwise.
void fft(std::vector<Complex>& data, int sign);

// The same over both axes of an n x n row-major grid.
void fft2d(std::vector<Complex>& grid, std::size_t n, int sign);

}  // namespace lenslab
