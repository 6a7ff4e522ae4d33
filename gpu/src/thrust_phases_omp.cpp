// The gpu/ module's Thrust code on Thrust's OpenMP system, compiled by the host
// compiler: the backend of machines without a CUDA device.

#define THRUST_DEVICE_SYSTEM THRUST_DEVICE_SYSTEM_OMP
#define PCL_TDA_GPU_BACKEND omp_backend

#include "thrust_phases.inl"
