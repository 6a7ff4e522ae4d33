#pragma once

/** \brief Marks a function that code compiled by nvcc may call on the GPU as well as
 * on the host (`__host__ __device__`); empty for host compilers. The distance and
 * radius test of point3d.h carry it, so that the gpu/ module's Thrust kernels and
 * the CPU builders compute edge values with one piece of code. */
#ifdef __CUDACC__
#define PCL_TDA_HOST_DEVICE __host__ __device__
#else
#define PCL_TDA_HOST_DEVICE
#endif
