#define FINBOOK_SUPERNODAL_ISA baseline
#define FINBOOK_SUPERNODAL_EIGEN finbook_eigen_baseline
#include "numeric_kernel.inc"
