#pragma once
// The no-penetration condition of boundary bodies (walls), shared by both precisions
// (reference: cpu_reference/wall_exclusion.hpp, float: kernels/common/wall_exclusion.hpp).
//
// Why: a wall is a few lattice planes of boundary particles at spacing dx, and the only thing that
// holds fluid back is the pressure force of eq. 7 between it and them. Inside a plane a square
// lattice leaves holes whose largest empty circle has radius dx / sqrt(2), and the net push on a
// particle in a hole is only the difference between the pressures on its two sides; a fluid
// particle squeezed hard enough (a heavy sphere settling on the floor, a fast impact near a
// corner) goes through and falls out of the tank.
//
// The condition: a fluid or deformable particle may not move to within a distance
// d_wall = kWallExclusionFraction dx of any boundary particle while coming closer to it. A step
// that would do so is rejected for that particle: it stays at its last position, which obeyed the
// condition, and loses the part of its velocity that points into the offending boundary particles
// (a perfectly inelastic collision with the wall, restitution 0: the position-level collision
// handling of Mueller, Charypar and Gross 2003, "Particle-based fluid simulation for interactive
// applications", SCA, section 6, with the wall known as its particles instead of an implicit
// surface). No force is added and nothing changes while particles keep their distance, so runs in
// which no particle comes that close are unchanged bit for bit.
//
// Why 0.8 dx: any d_wall above dx / sqrt(2) ~ 0.707 dx closes the holes of a boundary plane, so a
// particle can no longer pass between its particles. Fluid next to a wall sits at about dx from the
// nearest boundary particles (the fluid lattice continues the wall's), jittered by a few per cent
// and compressed by the equation of state's ~2 % density variation (c = 10 |v|max in the shipped
// scenes), so it stays well outside 0.8 dx unless it is being forced through the wall.
namespace mssph {

inline constexpr double kWallExclusionFraction = 0.8;  // d_wall / dx [-]

}  // namespace mssph
