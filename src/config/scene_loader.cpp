#include "config/scene_loader.hpp"

#include "config/haptics_config.hpp"
#include "config/input_file.hpp"
#include "config/json_reader.hpp"
#include "config/strict_json.hpp"
#include "util/errors.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace mssph {
namespace {

using Eigen::Vector3d;

// Steps and haptic ticks a run may take: beyond this a run is not a benchmark or a validation
// but a mistake (a dt of 5e-324, a duration of 1e308), and it could not finish in any case.
constexpr double kMaxSteps = 1e9;
// Haptic ticks within one step (a device at 1 kHz and a 10 ms step make 10).
constexpr double kMaxTicksPerStep = 1e4;

// Material keys that only deformable bodies may carry inline.
constexpr const char* kElasticKeys[] = {"young_modulus",
                                        "poisson_ratio",
                                        "model",
                                        "strain",
                                        "damping",
                                        "viscous_modulus",
                                        "zero_energy_stiffness",
                                        "kernel_gradient_correction"};

bool is_elastic_key(const std::string& key) {
  for (const char* k : kElasticKeys) {
    if (key == k) return true;
  }
  return false;
}

// `model`, or its older spelling `strain` (the strain measure of the linear stress law:
// green_saint_venant is stvk, cauchy in the rotated frame is corotated linear elasticity).
ElasticModel read_elastic_model(const JsonReader& reader, ElasticModel fallback) {
  if (reader.has("model") && reader.has("strain")) {
    reader.fail("strain",
                "give either model or strain (its older spelling: green_saint_venant = stvk, cauchy = "
                "corotated), not both");
  }
  if (reader.has("strain")) {
    return reader.choice("strain", {"green_saint_venant", "cauchy"}) == "cauchy" ? ElasticModel::corotated_linear
                                                                                 : ElasticModel::saint_venant_kirchhoff;
  }
  if (!reader.has("model")) return fallback;
  const std::string model = reader.choice("model", {"stvk", "corotated", "neo_hookean"});
  if (model == "corotated") return ElasticModel::corotated_linear;
  if (model == "neo_hookean") return ElasticModel::neo_hookean;
  return ElasticModel::saint_venant_kirchhoff;
}

// Reads the material keys present in `reader` on top of `material`.
void read_material_keys(const JsonReader& reader, Material& material) {
  material.rest_density = reader.number_or("rest_density", material.rest_density, Interval::positive());
  material.pressure_stiffness =
      reader.number_or("pressure_stiffness", material.pressure_stiffness, Interval::positive());
  material.viscosity = reader.number_or("viscosity", material.viscosity, Interval::non_negative());
  material.young_modulus = reader.number_or("young_modulus", material.young_modulus, Interval::positive());
  material.poisson_ratio = reader.number_or("poisson_ratio", material.poisson_ratio, Interval::open(-1.0, 0.5));
  material.model = read_elastic_model(reader, material.model);
  material.damping = reader.number_or("damping", material.damping, Interval::non_negative());
  material.viscous_modulus = reader.number_or("viscous_modulus", material.viscous_modulus, Interval::non_negative());
  material.zero_energy_stiffness =
      reader.number_or("zero_energy_stiffness", material.zero_energy_stiffness, Interval::non_negative());
  material.kernel_gradient_correction =
      reader.boolean_or("kernel_gradient_correction", material.kernel_gradient_correction);
}

struct MaterialEntry {
  Material material;
  bool has_young = false;
  bool has_poisson = false;
};

std::map<std::string, MaterialEntry> read_materials(const JsonReader& root) {
  std::map<std::string, MaterialEntry> materials;
  const auto section = root.optional_child("materials");
  if (!section) return materials;
  for (const auto& [name, reader] : section->members()) {
    reader.allow_only({"rest_density", "pressure_stiffness", "viscosity", "young_modulus", "poisson_ratio", "model",
                       "strain", "damping", "viscous_modulus", "zero_energy_stiffness", "kernel_gradient_correction",
                       "description"});
    reader.string_or("description", "");  // documentation only, but a string like everywhere else
    MaterialEntry entry;
    read_material_keys(reader, entry.material);
    entry.has_young = reader.has("young_modulus");
    entry.has_poisson = reader.has("poisson_ratio");
    materials.emplace(name, entry);
  }
  return materials;
}

SimulationConfig read_simulation(const JsonReader& root) {
  const JsonReader s = root.child("simulation");
  s.allow_only({"dt", "duration", "gravity", "particle_spacing", "smoothing_length", "seed", "jitter", "max_speed",
                "domain", "max_lost_mass_fraction", "viscosity_model", "sample_rigid_interiors", "neighbour_lists"});
  SimulationConfig sim;
  sim.dt = s.number("dt", Interval::positive());
  sim.duration = s.number("duration", Interval::positive());
  if (sim.dt > sim.duration) s.fail("dt", "expected dt <= duration (" + std::to_string(sim.duration) + " s)");
  if (sim.duration / sim.dt > kMaxSteps) {
    std::ostringstream message;
    message << "expected at most " << kMaxSteps << " steps (duration / dt), got " << sim.duration / sim.dt
            << " (duration " << sim.duration << " s, dt " << sim.dt << " s)";
    s.fail_here(message.str());
  }
  sim.gravity = s.vec3_or("gravity", sim.gravity);
  sim.particle_spacing = s.number("particle_spacing", Interval::positive());
  // At most 1 km: beyond, the smoothing length, particle volumes and memory figures derived from
  // it overflow (a spacing of 1e308 m made "about 1 particles need about inf EiB").
  if (sim.particle_spacing > 1e3) {
    s.fail("particle_spacing", "expected at most 1000 m, got " + std::to_string(sim.particle_spacing));
  }
  sim.smoothing_length = s.number_or("smoothing_length", 2.0 * sim.particle_spacing, Interval::positive());
  if (sim.smoothing_length < sim.particle_spacing || sim.smoothing_length > 4.0 * sim.particle_spacing) {
    s.fail("smoothing_length", "expected a support radius h between 1 and 4 particle spacings (" +
                                   std::to_string(sim.particle_spacing) + " m), got " +
                                   std::to_string(sim.smoothing_length));
  }
  sim.seed = static_cast<std::uint64_t>(s.integer_or("seed", 0, Interval::non_negative()));
  sim.jitter = s.number_or("jitter", 0.0, Interval{0.0, 0.25, false, false});
  sim.max_speed = s.number_or("max_speed", 50.0, Interval::positive());
  if (const auto domain = s.optional_child("domain")) {
    domain->allow_only({"min", "max"});
    const Region box{domain->vec3("min"), domain->vec3("max")};
    if ((box.min.array() >= box.max.array()).any()) domain->fail("max", "expected max > min in every axis");
    sim.domain = box;
  }
  sim.max_lost_mass_fraction = s.number_or("max_lost_mass_fraction", 0.001, Interval{0.0, 1.0, false, false});
  sim.viscosity_model = s.choice_or("viscosity_model", "paper", {"paper", "full_stress"}) == "full_stress"
                            ? ViscosityModel::full_stress
                            : ViscosityModel::paper;
  sim.sample_rigid_interiors = s.boolean_or("sample_rigid_interiors", false);
  sim.neighbour_lists = s.choice_or("neighbour_lists", "auto", {"auto", "always"}) == "always"
                            ? NeighbourListUse::always
                            : NeighbourListUse::automatic;
  return sim;
}

Shape read_shape(const JsonReader& body, double smoothing_length, double spacing) {
  const JsonReader s = body.child("shape");
  if (!s.value().is_object()) s.fail_here("expected an object with a \"type\"");
  const std::string type = s.choice("type", {"box", "sphere", "container", "spherical_container"});
  // A container's wall thickness: by default enough layers that a particle touching the wall sees
  // a full kernel support of wall.
  const auto read_wall_layers = [&] {
    const auto default_layers = static_cast<long long>(std::ceil(smoothing_length / spacing - 1e-9));
    return static_cast<int>(s.integer_or("wall_layers", default_layers, Interval::closed(1, 16)));
  };
  Shape shape;
  if (type == "box") {
    s.allow_only({"type", "size"});
    shape.type = ShapeType::box;
    shape.size = s.vec3("size", Interval::positive());
  } else if (type == "sphere") {
    s.allow_only({"type", "radius"});
    shape.type = ShapeType::sphere;
    shape.radius = s.number("radius", Interval::positive());
  } else if (type == "spherical_container") {
    s.allow_only({"type", "inner_radius", "wall_layers"});
    shape.type = ShapeType::spherical_container;
    shape.radius = s.number("inner_radius", Interval::positive());
    shape.wall_layers = read_wall_layers();
  } else {
    s.allow_only({"type", "inner_size", "wall_layers", "open_top"});
    shape.type = ShapeType::container;
    shape.size = s.vec3("inner_size", Interval::positive());
    shape.wall_layers = read_wall_layers();
    shape.open_top = s.boolean_or("open_top", true);
  }
  return shape;
}

BodyKind read_kind(const JsonReader& body) {
  const std::string kind = body.choice("kind", {"fluid", "deformable", "rigid", "boundary"});
  if (kind == "fluid") return BodyKind::fluid;
  if (kind == "deformable") return BodyKind::deformable;
  if (kind == "rigid") return BodyKind::rigid;
  return BodyKind::boundary;
}

BodyConfig read_body(const std::string& name, const JsonReader& reader,
                     const std::map<std::string, MaterialEntry>& materials, const SimulationConfig& sim) {
  reader.allow_only({"kind",
                     "shape",
                     "position",
                     "orientation",
                     "velocity",
                     "angular_velocity",
                     "material",
                     "rest_density",
                     "pressure_stiffness",
                     "viscosity",
                     "young_modulus",
                     "poisson_ratio",
                     "model",
                     "strain",
                     "damping",
                     "viscous_modulus",
                     "zero_energy_stiffness",
                     "kernel_gradient_correction",
                     "density",
                     "fixed",
                     "fixed_regions",
                     "fill_around_bodies",
                     "description"});
  // The name becomes the run log's HDF5 group /bodies/<name>, where '/' would nest groups, "."
  // would be /bodies itself, and a NUL character would end the name.
  if (name.empty() || name == "." || name.find_first_of(std::string("/\0", 2)) != std::string::npos) {
    reader.fail_here(
        "expected a body name that is non-empty and has no '/' or NUL character, and is not \".\" (it names the "
        "HDF5 group /bodies/<name>)");
  }
  reader.string_or("description", "");  // documentation only, but a string like everywhere else
  BodyConfig body;
  body.name = name;
  body.kind = read_kind(reader);

  // Keys that only mean something for some kinds are rejected elsewhere, so a typo in intent
  // ("young_modulus" on a fluid) is caught instead of silently ignored.
  for (const auto& [key, unused] : reader.value().items()) {
    (void)unused;
    if (is_elastic_key(key) && body.kind != BodyKind::deformable) {
      reader.fail(key, std::string("applies to deformable bodies only (this body is ") + to_string(body.kind) + ")");
    }
    if ((key == "density" || key == "fixed" || key == "angular_velocity") && body.kind != BodyKind::rigid) {
      reader.fail(key, std::string("applies to rigid bodies only (this body is ") + to_string(body.kind) + ")");
    }
    if (key == "fixed_regions" && body.kind != BodyKind::deformable) {
      reader.fail(key, std::string("applies to deformable bodies only (this body is ") + to_string(body.kind) + ")");
    }
    if (key == "velocity" && body.kind == BodyKind::boundary) {
      reader.fail(key, "a boundary does not move");
    }
    if (key == "fill_around_bodies" && body.kind != BodyKind::fluid) {
      reader.fail(key, std::string("applies to fluid bodies only (this body is ") + to_string(body.kind) + ")");
    }
  }

  body.shape = read_shape(reader, sim.smoothing_length, sim.particle_spacing);
  const bool container = body.shape.type == ShapeType::container || body.shape.type == ShapeType::spherical_container;
  if (container && body.kind != BodyKind::boundary) {
    reader.child("shape").fail("type", "a container is a boundary shape; use kind \"boundary\"");
  }
  body.position = reader.vec3_or("position", body.position);
  body.orientation = reader.quaternion_or("orientation", body.orientation);
  body.velocity = reader.vec3_or("velocity", body.velocity);
  body.angular_velocity = reader.vec3_or("angular_velocity", body.angular_velocity);

  bool has_young = reader.has("young_modulus");
  bool has_poisson = reader.has("poisson_ratio");
  if (reader.has("material")) {
    const std::string material_name = reader.string("material");
    const auto it = materials.find(material_name);
    if (it == materials.end()) {
      std::string known;
      for (const auto& [n, unused] : materials) known += (known.empty() ? "" : ", ") + n;
      reader.fail("material", "no material named \"" + material_name + "\" in /materials" +
                                  (known.empty() ? std::string(" (there are none)") : " (known: " + known + ")"));
    }
    body.material = it->second.material;
    has_young = has_young || it->second.has_young;
    has_poisson = has_poisson || it->second.has_poisson;
  }
  read_material_keys(reader, body.material);

  const auto require = [&](bool present, const char* key, const char* why) {
    if (!present) reader.fail(key, std::string("missing (inline or through \"material\"): ") + why);
  };
  const Material& m = body.material;
  require(m.rest_density > 0.0, "rest_density", "the SPH rest density rho0 [kg/m^3] of every body");
  require(m.pressure_stiffness > 0.0, "pressure_stiffness",
          "the pressure stiffness k [m^2/s^2] of every body, used by interaction forces (paper eq. 7)");
  if (body.kind == BodyKind::deformable) {
    require(has_young, "young_modulus", "Young's modulus E [Pa] of a deformable body");
    require(has_poisson, "poisson_ratio", "Poisson's ratio nu of a deformable body");
    // Only with the correction is sum_j X_ij (x) d_ij = I, so that a rigid rotation has no strain
    // rate and the viscous stress leaves a spinning body alone.
    if (m.viscous_modulus > 0.0 && !m.kernel_gradient_correction) {
      reader.fail("kernel_gradient_correction",
                  "expected true where viscous_modulus > 0 (inline or through \"material\"): without it the "
                  "strain rate of a rigid rotation is not zero, and the viscous stress would slow a spinning body");
    }
  }
  if (body.kind == BodyKind::rigid) {
    body.density = reader.number("density", Interval::positive());
    body.fixed = reader.boolean_or("fixed", false);
  }
  if (body.kind == BodyKind::fluid) body.fill_around_bodies = reader.boolean_or("fill_around_bodies", false);
  if (const auto regions = reader.optional_child("fixed_regions")) {
    for (const JsonReader& r : regions->elements()) {
      r.allow_only({"min", "max"});
      Region region{r.vec3("min"), r.vec3("max")};
      if ((region.min.array() > region.max.array()).any()) r.fail("max", "expected max >= min in every axis");
      body.fixed_regions.push_back(region);
    }
  }
  return body;
}

std::optional<ProxyConfig> read_proxy(const JsonReader& root, const std::vector<BodyConfig>& bodies) {
  const auto section = root.optional_child("proxy");
  if (!section) return std::nullopt;
  ProxyConfig proxy;
  proxy.haptics = read_haptics_config(*section);
  proxy.body = section->string("body");
  const auto it = std::find_if(bodies.begin(), bodies.end(), [&](const BodyConfig& b) { return b.name == proxy.body; });
  if (it == bodies.end()) section->fail("body", "no body named \"" + proxy.body + "\" in /bodies");
  const double ticks = proxy.haptics.haptic_rate_hz * root.child("simulation").number("duration");
  if (ticks > kMaxSteps) {
    std::ostringstream message;
    message << "expected at most " << kMaxSteps << " haptic ticks in the run (haptic_rate_hz x duration), got "
            << ticks;
    section->fail("haptic_rate_hz", message.str());
  }
  // A signal is looked at between steps: one step's ticks must not take long.
  const double ticks_per_step = proxy.haptics.haptic_rate_hz * root.child("simulation").number("dt");
  if (ticks_per_step > kMaxTicksPerStep) {
    std::ostringstream message;
    message << "expected at most " << kMaxTicksPerStep << " haptic ticks per step (haptic_rate_hz x dt), got "
            << ticks_per_step;
    section->fail("haptic_rate_hz", message.str());
  }
  if (it->kind != BodyKind::rigid || it->fixed) {
    section->fail("body", "the proxy must be a movable rigid body; \"" + proxy.body + "\" is " +
                              (it->fixed ? std::string("a fixed rigid body") : std::string(to_string(it->kind))));
  }
  return proxy;
}

OutputConfig read_output(const JsonReader& root, const SimulationConfig& sim) {
  OutputConfig out;
  const auto section = root.optional_child("output");
  if (!section) return out;
  section->allow_only({"log_interval", "snapshot_interval", "flush_interval"});
  out.log_interval = section->number_or("log_interval", 0.0, Interval::non_negative());
  if (out.log_interval > 0.0 && out.log_interval < sim.dt) {
    section->fail("log_interval", "expected 0 (every step) or at least dt = " + std::to_string(sim.dt) + " s");
  }
  out.snapshot_interval = section->number_or("snapshot_interval", 0.0, Interval::non_negative());
  out.flush_interval = section->number_or("flush_interval", 2.0, Interval::positive());
  return out;
}

// A string is stored in the run log and printed; the JSON library requires UTF-8.
bool is_valid_utf8(const std::string& text) {
  try {
    (void)nlohmann::json(text).dump();
    return true;
  } catch (const nlohmann::json::type_error&) {
    return false;
  }
}

}  // namespace

const char* to_string(BodyKind kind) {
  switch (kind) {
    case BodyKind::fluid:
      return "fluid";
    case BodyKind::deformable:
      return "deformable";
    case BodyKind::rigid:
      return "rigid";
    case BodyKind::boundary:
      return "boundary";
  }
  return "?";
}

const char* to_string(ElasticModel model) {
  switch (model) {
    case ElasticModel::saint_venant_kirchhoff:
      return "stvk";
    case ElasticModel::corotated_linear:
      return "corotated";
    case ElasticModel::neo_hookean:
      return "neo_hookean";
  }
  return "?";
}

const BodyConfig* Scene::find_body(const std::string& body_name) const {
  for (const BodyConfig& b : bodies) {
    if (b.name == body_name) return &b;
  }
  return nullptr;
}

void apply_override(nlohmann::json& document, const std::string& assignment) {
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0) {
    throw InputError("--set " + assignment + ": expected PATH=VALUE, e.g. bodies/block/young_modulus=5e4");
  }
  std::string path = assignment.substr(0, equals);
  const std::string text = assignment.substr(equals + 1);
  if (path.front() != '/') path = "/" + path;

  if (!is_valid_utf8(assignment)) {
    throw InputError(is_valid_utf8(path) ? "--set " + path + "=...: the value is not valid UTF-8 text"
                                         : std::string("--set: a PATH=VALUE argument is not valid UTF-8 text"));
  }
  nlohmann::json value;
  try {
    value = parse_strict_json(text, "--set " + path);
  } catch (const JsonSyntaxError&) {
    value = text;  // a bare word, e.g. strain=cauchy
  } catch (const InputError& e) {
    throw InputError(e.what(), path);
  }
  nlohmann::json::json_pointer pointer;
  try {
    pointer = nlohmann::json::json_pointer(path);
  } catch (const nlohmann::json::exception& e) {
    throw InputError("--set " + assignment + ": invalid path: " + e.what());
  }
  const auto parent = pointer.parent_pointer();
  if (!document.contains(parent) || !document.at(parent).is_object()) {
    throw InputError("--set " + assignment + ": " + parent.to_string() + " is not an object in the scene");
  }
  document[pointer] = value;
}

Scene parse_scene(const nlohmann::json& document, const std::string& file) {
  const JsonReader root(document, file);
  if (!document.is_object()) root.fail_here("expected a scene object");
  root.allow_only({"$schema", "name", "description", "simulation", "materials", "bodies", "proxy", "output"});

  root.string_or("$schema", "");  // only for editors, which expect a string (a schema URI or path)
  Scene scene;
  scene.source_file = file;
  scene.document = document;
  scene.name = root.string("name");
  // It names output files: a space, slash or control character (a newline, NUL) has no place there.
  const bool plain = std::none_of(scene.name.begin(), scene.name.end(), [](char c) {
    const auto byte = static_cast<unsigned char>(c);
    return byte < 0x20 || byte == 0x7f || c == ' ' || c == '/' || c == '\\';
  });
  if (scene.name.empty() || !plain) {
    root.fail("name",
              "expected a non-empty name without spaces or slashes, nor control characters (it names output files)");
  }
  // A NUL character would end the name where a file name is made of it.
  if (scene.name.find('\0') != std::string::npos) root.fail("name", "expected a name without a NUL character");
  scene.description = root.string_or("description", "");
  scene.simulation = read_simulation(root);
  const auto materials = read_materials(root);
  const JsonReader bodies = root.child("bodies");
  for (const auto& [name, reader] : bodies.members()) {
    scene.bodies.push_back(read_body(name, reader, materials, scene.simulation));
  }
  if (scene.bodies.empty()) bodies.fail_here("expected at least one body");
  scene.proxy = read_proxy(root, scene.bodies);
  scene.output = read_output(root, scene.simulation);
  return scene;
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides) {
  return parse_scene_text(read_input_file(path, "scene file"), path, overrides);
}

Scene parse_scene_text(const std::string& text, const std::string& path, const std::vector<std::string>& overrides) {
  nlohmann::json document = parse_strict_json(text, path);
  for (const std::string& assignment : overrides) {
    try {
      apply_override(document, assignment);
    } catch (const InputError& e) {
      throw InputError(path + ": " + e.what(), e.json_pointer());  // which scene the override was meant for
    }
  }
  try {
    return parse_scene(document, path);
  } catch (const InputError& e) {
    throw noting_override(e, overrides);
  }
}

InputError noting_override(const InputError& e, const std::vector<std::string>& overrides) {
  // A rejected value the user typed on the command line is not in the file they will open.
  const std::string& rejected = e.json_pointer();
  for (auto o = overrides.rbegin(); o != overrides.rend() && !rejected.empty(); ++o) {
    std::string set_path = o->substr(0, o->find('='));
    if (set_path.empty() || set_path.front() != '/') set_path = "/" + set_path;
    // The value itself, inside it, or the object holding it (a rule over several keys).
    const bool inside =
        rejected == set_path || rejected.rfind(set_path + "/", 0) == 0 || set_path.rfind(rejected + "/", 0) == 0;
    if (inside) return InputError(std::string(e.what()) + " (this value comes from --set " + *o + ")", rejected);
  }
  return e;
}

}  // namespace mssph
