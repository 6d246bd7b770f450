// The registry of validation cases, in the order they run. A new case: a folder with its
// scene, README and measuring code, its function declared in framework/case_functions.hpp, and
// one line here (see README.md).
#include "framework/case_functions.hpp"

namespace mssph::validation {

const std::vector<ValidationCase>& all_cases() {
  static const std::vector<ValidationCase> cases{
      {"kernels", "one_step", "kernels/one_step", "one force evaluation, float32 backends vs float64 reference",
       run_one_step_case},
      {"kernels", "sphere_drops", "kernels/sphere_drops", "Figure 3 sphere drops over 0.5 s, float32 vs reference",
       run_sphere_drops_case},
      {"kernels", "haptic_scenes", "kernels/haptic_scenes",
       "tap, squeeze and stir from their run logs, float32 vs reference", run_haptic_scenes_case},
      {"physics", "hydrostatic", "physics/hydrostatic", "slope of pressure against depth in a settled column vs rho0 g",
       run_hydrostatic_case},
      {"physics", "archimedes", "physics/archimedes", "floating depth of spheres of density 500 and 700 in water",
       run_archimedes_case},
      {"physics", "shear_decay", "physics/shear_decay",
       "viscous decay of a shear wave in a free block vs Stokes' solution", run_shear_decay_case},
      {"physics", "plate_shear", "physics/plate_shear",
       "drag of an impulsively started plate under a fluid layer vs Stokes' first problem", run_plate_shear_case},
      {"physics", "rotating_sphere", "physics/rotating_sphere",
       "viscous torque on a sphere turning in a concentric spherical container vs Kirchhoff, two viscosities",
       run_rotating_sphere_case},
      {"physics", "translating_sphere", "physics/translating_sphere",
       "drag on a sphere towed through closed cubes, extrapolated to Stokes' 6 pi mu R V", run_translating_sphere_case},
      {"physics", "dam_break", "physics/dam_break",
       "surge front of a collapsing water column vs Martin and Moyce 1952, Koshizuka and Oka 1996", run_dam_break_case},
      {"physics", "torque_free_spin", "physics/torque_free_spin", "a tumbling box keeps its angular momentum",
       run_torque_free_spin_case},
      {"physics", "rotation_invariance", "physics/rotation_invariance",
       "rigid rotations give R_i = Q and no elastic force", run_rotation_invariance_case},
      {"physics", "patch_tests", "physics/patch_tests", "uniaxial stress, uniaxial strain and simple shear give C eps",
       run_patch_tests_case},
      {"physics", "bar_vibration", "physics/bar_vibration", "free bar: longitudinal period, energy drift, damping rate",
       run_bar_vibration_case},
      {"physics", "cantilever", "physics/cantilever", "cantilever tip deflection under gravity vs Euler-Bernoulli",
       run_cantilever_case},
      {"physics", "cantilever_frequency", "physics/cantilever_frequency",
       "cantilever first bending frequency vs Euler-Bernoulli", run_cantilever_frequency_case},
      {"physics", "hertz", "physics/hertz", "Hertz contact: exponent 1.5 and prefactor 4/3 E* sqrt(R)", run_hertz_case},
      {"physics", "hertz_impact", "physics/hertz_impact",
       "sphere striking an elastic block: indentation, peak force and pulse vs Hertz's impact theory",
       run_hertz_impact_case},
      {"physics", "coupling_step", "physics/coupling_step", "coupling step responses vs the damped oscillator",
       run_coupling_step_case},
      {"physics", "passivity", "physics/passivity", "the coupling injects no energy over a 5 s script",
       run_passivity_case},
      {"convergence", "hydrostatic_slope", "convergence/hydrostatic_slope", "dP/dz at three spacings",
       run_hydrostatic_convergence_case},
      {"convergence", "floating_depth", "convergence/floating_depth", "floating depth at three spacings",
       run_floating_convergence_case},
      {"convergence", "cantilever_deflection", "convergence/cantilever_deflection",
       "cantilever tip deflection at three spacings vs Timoshenko", run_cantilever_convergence_case},
      {"selftest", "wrong_expectation", "selftest/wrong_expectation",
       "a flat-punch force curve judged against Hertz: must FAIL", run_wrong_expectation_case},
  };
  return cases;
}

}  // namespace mssph::validation
