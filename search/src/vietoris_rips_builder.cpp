#include <pcl/impl/instantiate.hpp>
#include <pcl/tda/common/point_types.h>
#include <pcl/tda/search/vietoris_rips_builder.h>
#include <pcl/point_types.h>

#ifndef PCL_NO_PRECOMPILE
#include <pcl/tda/search/impl/vietoris_rips_builder.hpp>

PCL_INSTANTIATE (VietorisRipsBuilder, PCL_TDA_XYZ_POINT_TYPES)
#endif // PCL_NO_PRECOMPILE
