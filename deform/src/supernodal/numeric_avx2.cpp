#define FINBOOK_SUPERNODAL_ISA avx2
#define FINBOOK_SUPERNODAL_EIGEN finbook_eigen_avx2
#include "numeric_kernel.inc"
