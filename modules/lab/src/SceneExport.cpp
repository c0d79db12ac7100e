#include "pm/lab/SceneExport.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <utility>

#include <nlohmann/json.hpp>

#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"
#include "pm/io/ViewsFolder.h"
#include "pm/lab/LabPass.h"
#include "pm/robot/ArmCatalog.h"
#include "pm/robot/SteppedArm.h"
#include "pm/sim/MeshOutlineCut.h"
#include "pm/sim/Scene.h"
#include "pm/sim/TargetCatalog.h"
#include "pm/sim/Trajectory.h"

namespace pm::lab {

namespace fs = std::filesystem;

void SceneExportParams::validate() const
{
  auto check = [](bool ok, const std::string &what) {
    if (!ok)
      throw core::Error("scene export: " + what);
  };
  check(sim::isCatalogTarget(target) || sim::isReliefTarget(target), "unknown target '" + target + "' (C01..C12, R1..R3)");
  check(backdrop == "sea-bottom" || backdrop == "cloth", "unknown backdrop '" + backdrop + "' (sea-bottom or cloth)");
  check(stillGapMm >= 0 && stillGapMm <= 500, "the still backdrop's gap must lie in [0, 500] mm");
  check(!waypoints.empty(), "the sequence needs at least one waypoint");
  check(holdS >= 0 && moveS > 0 && fps > 0, "hold >= 0, move > 0 and fps > 0 are needed");
  check(lightSizeMm > 0, "the light's size must be positive");
  plan.validate();
}

namespace {

//! A 4x4 matrix as JSON rows (metres).
nlohmann::json matrixJson(const vpHomogeneousMatrix &M)
{
  nlohmann::json rows = nlohmann::json::array();
  for (unsigned i = 0; i < 4; ++i)
    rows.push_back({M[i][0], M[i][1], M[i][2], M[i][3]});
  return rows;
}

//! \e mesh as an OBJ (positions, texture coordinates over \e texture's size, normals) using material \e name from \e name.mtl.
void writeObj(const sim::Mesh &mesh, const std::string &name, const fs::path &dir)
{
  const double w = mesh.texture ? mesh.texture->width : 1, h = mesh.texture ? mesh.texture->height : 1;
  std::ofstream obj(dir / (name + ".obj"));
  obj << "# " << name << ": metres, in its own frame (x right, y down, z away from the viewer)\nmtllib " << name << ".mtl\nusemtl "
      << name << "\n"
      << std::setprecision(7);
  for (const auto &v : mesh.vertices)
    obj << "v " << v.x << " " << v.y << " " << v.z << "\n";
  for (const auto &v : mesh.vertices)
    obj << "vt " << (v.s + 0.5) / w << " " << 1 - (v.t + 0.5) / h << "\n";
  for (const auto &v : mesh.vertices)
    obj << "vn " << v.nx << " " << v.ny << " " << v.nz << "\n";
  // Each face wound counter-clockwise seen from the side its normals face: a path tracer shades a face from its front.
  for (auto t : mesh.triangles) {
    const auto &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
    const double facing = (uy * vz - uz * vy) * (a.nx + b.nx + c.nx) + (uz * vx - ux * vz) * (a.ny + b.ny + c.ny) +
                          (ux * vy - uy * vx) * (a.nz + b.nz + c.nz);
    if (facing < 0)
      std::swap(t[1], t[2]);
    obj << "f";
    for (const auto i : t)
      obj << " " << i + 1 << "/" << i + 1 << "/" << i + 1;
    obj << "\n";
  }
  std::ofstream mtl(dir / (name + ".mtl"));
  mtl << "newmtl " << name << "\nKd 1 1 1\nmap_Kd " << name << "_texture.png\n";
  if (!obj || !mtl)
    throw core::Error("cannot write " + (dir / (name + ".obj")).string());
  if (mesh.texture) {
    const sim::Texture &t = *mesh.texture;
    vpImage<vpRGBa> I(static_cast<unsigned>(t.height), static_cast<unsigned>(t.width));
    for (unsigned i = 0; i < I.getSize(); ++i)
      I.bitmap[i] = vpRGBa(t.rgb[3 * i], t.rgb[3 * i + 1], t.rgb[3 * i + 2], 255);
    io::writeImage(I, (dir / (name + "_texture.png")).string());
  }
}

//! One camera of the rig for scene.json: its intrinsics, size and pose on the hand.
nlohmann::json cameraJson(const core::PinholeCamera &c)
{
  return {{"name", c.name},
          {"width", c.width},
          {"height", c.height},
          {"px", c.cam.get_px()},
          {"py", c.cam.get_py()},
          {"u0", c.cam.get_u0()},
          {"v0", c.cam.get_v0()},
          {"hMc", matrixJson(c.hMc)}};
}

//! The lab's own rendering of the sequence (our rasterizer), with the toy frame's truth.
void renderLabSequence(const sim::Scene &scene, const core::StereoRig &rig, const std::vector<vpHomogeneousMatrix> &hMo,
                       const std::vector<vpHomogeneousMatrix> &oMb, const fs::path &dir)
{
  fs::create_directories(dir);
  std::ofstream truth(dir / "truth.csv");
  truth << "frame,x,y,z,e1,e2,e3\n" << std::setprecision(10);
  char name[32];
  for (std::size_t k = 0; k < hMo.size(); ++k) {
    const sim::StereoImages im = scene.renderStereo(rig, hMo[k], k, oMb[k]);
    std::snprintf(name, sizeof name, "left_%04zu.png", k);
    io::writeImage(im.left, (dir / name).string());
    std::snprintf(name, sizeof name, "right_%04zu.png", k);
    io::writeImage(im.right, (dir / name).string());
    const core::Phi p = core::fromHomogeneousMatrix(hMo[k]);
    truth << k << "," << p.x << "," << p.y << "," << p.z << "," << p.e1 << "," << p.e2 << "," << p.e3 << "\n";
  }
  if (!truth)
    throw core::Error("cannot write " + (dir / "truth.csv").string());
}

} // namespace

void exportScene(const SceneExportParams &p, const core::StereoRig &rig, const std::string &dirName)
{
  p.validate();
  rig.validate();
  const fs::path dir(dirName), part(dirName + ".part");
  fs::remove_all(part);
  fs::create_directories(part);
  // The folder is written aside and put in place whole at the end; on an error nothing is left.
  struct Aside
  {
    fs::path path;
    bool done = false;
    ~Aside()
    {
      std::error_code ignored;
      if (!done)
        fs::remove_all(path, ignored);
    }
  } aside{part};

  sim::SceneParams sp;
  sp.stillBackdrop = p.stillBackdrop;
  sp.stillBackdropGapMm = p.stillGapMm;
  const sim::Scene scene(sim::makeTarget(p.target), sp);

  // The pass, made by the lab's arm as pm-make-model --target makes it; our renderer's views kept as its peer.
  robot::SteppedArm arm(robot::makeArmModel(p.arm));
  const LabPass pass = runLabPass(scene, rig, p.plan, arm, vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0));
  io::saveViewsFolder(pass.views, (part / "lab_views").string());

  // The sequence: the hand at its rest, the toy along the waypoints; the backdrop with the toy or still.
  const sim::Trajectory trajectory(p.waypoints, p.holdS, p.moveS);
  const auto frames = static_cast<std::size_t>(std::floor(trajectory.duration() * p.fps)) + 1;
  std::vector<vpHomogeneousMatrix> hMo, oMb;
  nlohmann::json seq = nlohmann::json::array();
  for (std::size_t k = 0; k < frames; ++k) {
    hMo.push_back(core::toHomogeneousMatrix(trajectory.at(static_cast<double>(k) / p.fps)));
    const vpHomogeneousMatrix fMo = pass.fMh0 * hMo.back();
    oMb.push_back(p.stillBackdrop ? fMo.inverse() * pass.fMo : vpHomogeneousMatrix());
    const core::Phi truth = core::fromHomogeneousMatrix(hMo.back());
    seq.push_back({{"fMh", matrixJson(pass.fMh0)},
                   {"fMo", matrixJson(fMo)},
                   {"fMb", matrixJson(p.stillBackdrop ? pass.fMo : fMo)},
                   {"hMo_phi", {truth.x, truth.y, truth.z, truth.e1, truth.e2, truth.e3}}});
  }
  renderLabSequence(scene, rig, hMo, oMb, part / "lab_sequence");

  // The geometry: the toy cut along its outline, the panel (in the toy's frame; still: its gap farther back).
  writeObj(sim::cutAlongOutline(sim::buildTargetMesh(scene.target(), sp.meshStepMm, static_cast<float>(sp.specular))), "toy", part);
  const double backdropZ = sp.backdropGapMm + (p.stillBackdrop ? p.stillGapMm : 0);
  writeObj(sim::makeBackdropMesh(sim::makeSeaBottomTexture(sp.seaBottom), sp.seaBottom, backdropZ), "backdrop", part);
  io::saveRig(rig, (part / "rig.json").string(), "rig_cameras.xml", "the rig the scene was exported for");

  nlohmann::json views = nlohmann::json::array();
  for (const auto &v : pass.views)
    views.push_back({{"fMh", matrixJson(v.fMh)}});
  const vpHomogeneousMatrix oMl(p.lightCentreMm[0] * 1e-3, p.lightCentreMm[1] * 1e-3, p.lightCentreMm[2] * 1e-3, 0, 0, 0);
  const nlohmann::json scenario = {
      {"format", "visp-photomodel-scene"},
      {"version", 1},
      {"units", "metres; poses as 4x4 row-major matrices in the world frame f (the arm's base)"},
      {"target", {{"code", scene.target().info.code}, {"name", scene.target().info.name}}},
      {"toy", {{"mesh", "toy.obj"}, {"roughness", 0.3}}},
      {"backdrop", {{"kind", p.backdrop}, {"mesh", "backdrop.obj"}, {"still", p.stillBackdrop}, {"gap_mm", backdropZ}}},
      {"light", {{"fMl_position", {(pass.fMo * oMl)[0][3], (pass.fMo * oMl)[1][3], (pass.fMo * oMl)[2][3]}},
                 {"aim", {pass.fMo[0][3], pass.fMo[1][3], pass.fMo[2][3]}},
                 {"size_m", p.lightSizeMm * 1e-3}}},
      {"cameras", {cameraJson(rig.left), cameraJson(rig.right)}},
      {"pass", {{"fMo", matrixJson(pass.fMo)}, {"views", views}}},
      {"sequence", {{"fps", p.fps}, {"frames", seq}}}};
  std::ofstream(part / "scene.json") << scenario.dump(1) << "\n";
  if (!fs::exists(part / "scene.json"))
    throw core::Error("cannot write " + (part / "scene.json").string());
  fs::remove_all(dir);
  fs::rename(part, dir);
  aside.done = true;
}

} // namespace pm::lab
