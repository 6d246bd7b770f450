#!/usr/bin/env bash
# CI's AddressSanitizer + UndefinedBehaviorSanitizer run: configures the asan-ubsan preset
# (build-asan/, clang++ -O1 -g1, host backends), builds the test programs below from nothing and
# runs their tests with `ctest --preset asan-ubsan`, which fails a test on any sanitizer report
# (undefined behaviour halts, leaks count; CMakePresets.json says how).
#
# The set fits CI's 30 minutes beside the rest of scripts/test.sh, from an empty build-asan with
# no compiler cache on 2 cores (results/reliability.md, "Fuzzing and sanitizers", and
# results/current/cpu-2core.md have the times). Every program links the whole library stack,
# which is most of the build; a program of its own adds a few seconds of compiling and linking.
set -euo pipefail
cd "$(dirname "$0")/.."

# The physics first: the float32 equations against their float64 twins, the cpu backend against
# the reference, the reference's own physics, then the model, scene, config and run-log code the
# backends are built from, and the CLI tests, which run the instrumented mssph itself (a sanitizer
# report there changes its exit code, which every CLI test checks).
programs=(
  equation_twins_test            # tests/equations: every kernels/common equation vs cpu_reference
  one_step_agreement_test        # tests/backends: one step, cpu vs reference
  backend_agreement_test         # tests/backends: the three sphere drops, 2000 steps, cpu vs reference
  read_back_test                 # tests/backends
  neighbour_list_test            # tests/backends: the host's neighbour lists vs the grid walk
  particle_partition_test        # tests/backends: the host loops' split among OpenMP threads
  wall_check_lanes_test          # tests/backends: the wall check split over a team of lanes
  grid_walk_test                 # tests/backends: each lane's share of the grid walk
  reference_unit_tests           # tests/reference: kernels, neighbour search
  rigid_physics_test             # tests/reference
  fluid_physics_test             # tests/reference (its two settling cases left out, below)
  deformable_rotation_test       # tests/deformable (seven of its programs left out, below)
  deformable_patch_test
  deformable_momentum_test
  deformable_material_model_test
  deformable_neo_hookean_dynamics_test
  deformable_zero_energy_test
  deformable_contact_layer_density_test
  deformable_sphere_drop_test
  deformable_compression_test
  deformable_compression_log_test
  haptics_unit_tests             # tests/haptics: coupling, haptics config, recordings
  haptics_physics_tests          # tests/haptics: step responses, multi-rate loop, passivity
  mssph_config_tests             # tests/config: JSON reader, scene loader, lattice, builder
  mssph_io_tests                 # tests/io: run logs written and read back
  mssph_sim_tests                # tests/sim: start-up stability checks
  mssph                          # run by mssph_cli_tests
  mssph_cli_tests                # tests/cli: exit codes, bad input, output safety, signals, validate
)

# Left out for time: each of these simulates seconds of settling or many periods, a minute to
# several under the sanitizers (results/reliability.md has the times). They run uninstrumented in
# scripts/test.sh; the same step functions run here in the shorter cases (the neo-Hookean body's
# spin, the zero-energy control's damped hourglass mode, the deformable sphere drop with its
# viscous modulus). Programs not built: deformable_cantilever_test,
# deformable_cantilever_frequency_test, deformable_hertz_test, deformable_hertz_impact_test,
# deformable_viscous_bar_test, deformable_bar_test, deformable_soft_block_rest_test. Single cases
# (the restart runs simulate 4.8 s of tap_squeeze_stir three times per backend; the checkpoint
# code runs here in mssph_io_tests' Checkpoints cases and the CLI's RestartRefusal cases; the
# three sphere drops, 2000 steps each on the cpu backend and the reference, while
# BackendAgreement.RunsAreBitIdentical runs the cpu backend's fluid and deformable drops here, and
# the reference's step runs in the physics programs above):
left_out=(
  'FluidPhysics\.SettledColumnHasHydrostaticPressure'
  'FluidPhysics\.LightSphereFloatsAtArchimedesDepth'
  'Momentum\.SpinningDeformedBodyKeepsAngularMomentumWithCorrection'
  'Backends/Restart\.[A-Za-z]+/(cpu|reference|cuda)'
  'FloatBackends/BackendAgreement\.(Fluid|Rigid|Deformable)DropFollowsTheReference/cpu'
)

# ctest's -E replaces the preset's name filter, so it repeats it: the <program>_NOT_BUILT tests
# that CMake registers for the programs not built here. A name ends at a space: a parameterised
# test's name goes on with "  # GetParam() = ...".
exclude="_NOT_BUILT\$|^($(IFS='|'; echo "${left_out[*]}"))( |\$)"

cmake --preset asan-ubsan
cmake --build --preset asan-ubsan --target "${programs[@]}"
# One OpenMP thread per test and as many tests at once as there are cores, as in scripts/test.sh.
OMP_NUM_THREADS=1 ctest --preset asan-ubsan -j "$(nproc)" -E "$exclude"
