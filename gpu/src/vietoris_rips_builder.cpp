#include <pcl/impl/instantiate.hpp>
#include <pcl/tda/common/point_types.h>
#include <pcl/tda/gpu/vietoris_rips_builder.h>
#include <pcl/point_types.h>

#ifndef PCL_NO_PRECOMPILE
#include <pcl/tda/gpu/impl/vietoris_rips_builder.hpp>

// The macro is named after the CPU class' with a prefix, so that both classes can be
// instantiated side by side.
PCL_INSTANTIATE (GPUVietorisRipsBuilder, PCL_TDA_XYZ_POINT_TYPES)
#endif // PCL_NO_PRECOMPILE
