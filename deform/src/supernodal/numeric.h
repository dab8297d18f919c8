// The numeric supernodal factorization on plain arrays, compiled once per instruction set
// (numeric_kernel.inc): Eigen's dense complex kernels run about 1.8× faster with AVX2 + FMA
// and 3× faster with AVX-512 than with the SSE2 baseline every x86-64 has, and the
// factorization spends almost all of its time in them. SupernodalCholesky picks the variant
// the running CPU supports. Nothing here uses std containers, so no inline library code
// compiled for a wider instruction set can stand in for the baseline's (see
// tst_supernodal_isa).
#pragma once

#include <complex>
#include <cstdint>

namespace finbook::deform::supernodal {

struct Pattern {
    int n = 0;
    int count = 0;                          // supernodes
    const int *first = nullptr;             // count + 1
    const int *superOf = nullptr;           // n
    const std::int64_t *rowStart = nullptr; // count + 1
    const int *rows = nullptr;
    const std::int64_t *valueStart = nullptr; // count + 1
};

// A's columns, entries on and below the diagonal used (compressed columns, optionally
// uncompressed with per-column counts in nonZeros).
template <class Scalar> struct Lower {
    const int *outer = nullptr;
    const int *inner = nullptr;
    const int *nonZeros = nullptr;
    const Scalar *values = nullptr;
};

// Scratch the caller owns: n + 3·count + maxRows ints, maxUpdate scalars for updates (see
// SupernodalSymbolic).
struct Scratch {
    int *map = nullptr, *head = nullptr, *link = nullptr, *position = nullptr, *relative = nullptr;
    void *update = nullptr;
};

// Fills L (zeroed, valueStart[count] entries); false when a pivot is not positive and finite.
#define FINBOOK_SUPERNODAL_DECLARE(isa)                                                            \
    namespace isa {                                                                                \
    bool factorize(const Pattern &p, const Lower<double> &a, double *L, const Scratch &s);         \
    bool factorize(const Pattern &p, const Lower<std::complex<double>> &a,                         \
                   std::complex<double> *L, const Scratch &s);                                     \
    }
FINBOOK_SUPERNODAL_DECLARE(baseline)
FINBOOK_SUPERNODAL_DECLARE(avx2)
FINBOOK_SUPERNODAL_DECLARE(avx512)
#undef FINBOOK_SUPERNODAL_DECLARE

} // namespace finbook::deform::supernodal
