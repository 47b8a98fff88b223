// Declarations of every field kind (one .cpp per kind defines its spec);
// registry.cpp gathers them. Internal to the field module.
#pragma once

#include "field/registry.h"

namespace sm::field {

KindSpec ball_kind();
KindSpec bathymetry_kind();
KindSpec boundary_layer_kind();
KindSpec box_kind();
KindSpec channel_width_kind();
KindSpec constant_kind();
KindSpec curvature_kind();
KindSpec cylinder_kind();
KindSpec distance_kind();
KindSpec gradation_kind();
KindSpec gradient_kind();
KindSpec laplacian_kind();
KindSpec lonlat_kind();
KindSpec math_eval_kind();
KindSpec max_eigen_hessian_kind();
KindSpec max_kind();
KindSpec mean_kind();
KindSpec min_kind();
KindSpec min_aniso_kind();
KindSpec param_kind();
KindSpec restrict_kind();
KindSpec structured_kind();
KindSpec threshold_kind();
KindSpec time_step_kind();

}  // namespace sm::field
