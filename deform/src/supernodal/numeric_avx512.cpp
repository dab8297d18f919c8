#define FINBOOK_SUPERNODAL_ISA avx512
#define FINBOOK_SUPERNODAL_EIGEN finbook_eigen_avx512
#include "numeric_kernel.inc"
