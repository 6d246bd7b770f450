"""One sphere-drop run log (configs/sphere_drop_*.json) as NumPy arrays: what Figure 3 draws and
checks. Only the HDF5 run log is read."""
import json

import h5py
import numpy as np

from figure_common import provenance, text_attribute

GRAVITY = 9.81  # [m/s^2], the shipped scenes' |g|


class DropLog:
    def __init__(self, path):
        self.path = path
        with h5py.File(path, "r") as h5:
            self.status = text_attribute(h5, "status")
            self.context = provenance(h5)
            config = json.loads(text_attribute(h5, "config"))
            self.scene = config["name"]
            self.spacing = config["simulation"]["particle_spacing"]
            self.gravity = float(np.linalg.norm(config["simulation"].get("gravity", [0, 0, -GRAVITY])))
            sphere_name = config["proxy"]["body"]
            sphere = config["bodies"][sphere_name]
            self.radius = sphere["shape"]["radius"]
            self.start_height = sphere["position"][2]
            block = config["bodies"]["block"]
            self.block_kind = block["kind"]
            self.block_top = block["position"][2] + 0.5 * block["shape"]["size"][2]
            block_material = config["materials"][block["material"]]
            self.fluid_density = block_material["rest_density"]
            self.young_modulus = block_material.get("young_modulus")
            self.poisson_ratio = block_material.get("poisson_ratio")
            body = h5["bodies"][sphere_name]
            self.mass = float(body.attrs["mass"])
            # The sphere's lattice sites, interior included; its particle_count leaves out the
            # interior beyond reach (src/model/rigid_interior.hpp).
            self.lattice_sites = int(body.attrs["lattice_sites"])
            self.time = h5["time"][:]
            self.z = body["centre_of_mass"][:, 2]
            self.vz = body["linear_momentum"][:, 2] / self.mass
            self.force = body["interaction_force"][:]
            self.haptic_time = h5["haptics/time"][:]
            self.coupling_force = h5["haptics/coupling/force"][:]
            self.rendered_force = h5["haptics/rendered/force"][:]
            self.max_injected_energy = float(h5["haptics"].attrs["max_injected_energy_J"])
            self.last_particles = None
            if "snapshots" in h5 and len(h5["snapshots"]):
                last = h5["snapshots"][sorted(h5["snapshots"].keys())[-1]]
                names = [n.decode() if isinstance(n, bytes) else str(n) for n in h5["particles"].attrs["body_names"]]
                bodies = h5["particles/body"][:]
                self.last_particles = {
                    "time": float(last.attrs["time"]),
                    "block": last["position"][:][bodies == names.index("block")],
                }

    @property
    def weight(self):
        return self.mass * self.gravity

    @property
    def fz(self):
        return self.force[:, 2]

    def settled(self, window):
        """Mask of the samples in the last `window` seconds."""
        return self.time >= self.time[-1] - window
