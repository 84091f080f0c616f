#pragma once
// Marks math shared between the CPU path and CUDA kernels: the CPU tests check the math,
// GPU runs check only the scheduling.
// CLS_UNROLL: full unrolling where nvcc would otherwise keep a loop and move its arrays to local memory.
#if defined(__CUDACC__)
#define CLS_HD __host__ __device__ __forceinline__
#define CLS_UNROLL _Pragma("unroll")
#else
#define CLS_HD inline
#define CLS_UNROLL
#endif
