#!/usr/bin/python3
"""First bending frequency of a clamped-free Timoshenko beam over Euler-Bernoulli's.

Used by validation/physics/cantilever_frequency: Timoshenko's beam (Timoshenko 1921; shear with
coefficient kappa and rotary inertia rho I) solved by finite elements (linear w and theta, one-point
shear integration against locking, consistent mass), refined until f1 stops changing. Prints f1 of
both theories for the validation cantilever (L = 0.24 m, square H = 0.04 m, E = 3 MPa, nu = 0.3,
rho = 1000 kg/m^3, kappa = 5/6) and their ratio. numpy only (Debian's python3-numpy).
"""
import argparse
import math

import numpy as np


def timoshenko_f1(length, side, young, nu, rho, kappa, elements):
    area, inertia = side * side, side ** 4 / 12.0
    shear = young / (2.0 * (1.0 + nu))
    le = length / elements
    n = 2 * (elements + 1)  # w, theta per node
    k, m = np.zeros((n, n)), np.zeros((n, n))
    bend = np.array([0.0, -1.0, 0.0, 1.0]) / le                 # theta'
    gamma = np.array([-1.0 / le, -0.5, 1.0 / le, -0.5])        # w' - theta at the element centre
    mass_1d = np.array([[2.0, 1.0], [1.0, 2.0]]) * le / 6.0
    for e in range(elements):
        dofs = [2 * e, 2 * e + 1, 2 * e + 2, 2 * e + 3]
        ke = young * inertia * le * np.outer(bend, bend) + kappa * shear * area * le * np.outer(gamma, gamma)
        me = np.zeros((4, 4))
        me[np.ix_([0, 2], [0, 2])] = rho * area * mass_1d
        me[np.ix_([1, 3], [1, 3])] = rho * inertia * mass_1d
        k[np.ix_(dofs, dofs)] += ke
        m[np.ix_(dofs, dofs)] += me
    free = slice(2, n)  # clamped at x = 0: w = theta = 0
    eig = np.linalg.eigvals(np.linalg.solve(m[free, free], k[free, free]))
    return math.sqrt(min(eig.real)) / (2.0 * math.pi)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--elements", type=int, default=400)
    a = parser.parse_args()
    length, side, young, nu, rho, kappa = 0.24, 0.04, 3.0e6, 0.3, 1000.0, 5.0 / 6.0
    euler_bernoulli = 1.8751 ** 2 / (2.0 * math.pi * length ** 2) * math.sqrt(young * side ** 2 / 12.0 / rho)
    coarse = timoshenko_f1(length, side, young, nu, rho, kappa, a.elements // 2)
    fine = timoshenko_f1(length, side, young, nu, rho, kappa, a.elements)
    print(f"Euler-Bernoulli f1 = {euler_bernoulli:.5f} Hz")
    print(f"Timoshenko f1 = {fine:.5f} Hz ({a.elements} elements; {coarse:.5f} with {a.elements // 2})")
    print(f"ratio = {fine / euler_bernoulli:.5f}")


if __name__ == "__main__":
    main()
