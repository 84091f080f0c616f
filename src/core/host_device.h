#pragma once
// Marks math shared between the CPU path and CUDA kernels: the CPU tests check the math,
// GPU runs check only the scheduling.
#if defined(__CUDACC__)
#define CLS_HD __host__ __device__ __forceinline__
#else
#define CLS_HD inline
#endif
