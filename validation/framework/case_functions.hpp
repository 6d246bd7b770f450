#pragma once
// The case functions of every suite, listed in validation/cases.cpp. Each lives in its case's
// folder beside its README and scene.
#include "framework/backends.hpp"
#include "framework/validation_case.hpp"

namespace mssph::validation {

// kernels
CaseResult run_one_step_case(const CaseContext& context);
CaseResult run_sphere_drops_case(const CaseContext& context);
CaseResult run_haptic_scenes_case(const CaseContext& context);

// physics
CaseResult run_hydrostatic_case(const CaseContext& context);
CaseResult run_archimedes_case(const CaseContext& context);
CaseResult run_dam_break_case(const CaseContext& context);
CaseResult run_shear_decay_case(const CaseContext& context);
CaseResult run_plate_shear_case(const CaseContext& context);
CaseResult run_rotating_sphere_case(const CaseContext& context);
CaseResult run_translating_sphere_case(const CaseContext& context);
CaseResult run_torque_free_spin_case(const CaseContext& context);
CaseResult run_rotation_invariance_case(const CaseContext& context);
CaseResult run_patch_tests_case(const CaseContext& context);
CaseResult run_bar_vibration_case(const CaseContext& context);
CaseResult run_cantilever_case(const CaseContext& context);
CaseResult run_cantilever_frequency_case(const CaseContext& context);
CaseResult run_hertz_case(const CaseContext& context);
CaseResult run_hertz_impact_case(const CaseContext& context);
CaseResult run_coupling_step_case(const CaseContext& context);
CaseResult run_passivity_case(const CaseContext& context);

// convergence
CaseResult run_hydrostatic_convergence_case(const CaseContext& context);
CaseResult run_floating_convergence_case(const CaseContext& context);
CaseResult run_cantilever_convergence_case(const CaseContext& context);

// test-only: a case whose expectation is deliberately wrong, selectable only by its name
CaseResult run_wrong_expectation_case(const CaseContext& context);

}  // namespace mssph::validation
