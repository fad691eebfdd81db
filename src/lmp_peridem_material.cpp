/* ----------------------------------------------------------------------
   PERIDEM: material files seen from LAMMPS commands.
------------------------------------------------------------------------- */

#include "lmp_peridem_material.h"

#include "error.h"
#include "lammps.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace PERIDEM {

peridem::Material load_material(LAMMPS *lmp, const std::string &command, const std::string &file,
                                const std::string &name)
{
  try {
    const peridem::MaterialFile materials = peridem::read_material_file(file);
    if (materials.units != lmp->update->unit_style)
      lmp->error->all(FLERR, "{}: material file {} is in units {} but the simulation uses units {}",
                      command, file, materials.units, lmp->update->unit_style);
    return materials.get(name);
  } catch (peridem::ParameterError &e) {
    lmp->error->all(FLERR, "{}: {}", command, e.what());
  }
  return {};
}

peridem::Micromodulus parse_micromodulus(LAMMPS *lmp, const std::string &command,
                                         const std::string &word)
{
  if (word == "constant") return peridem::Micromodulus::Constant;
  if (word == "conic") return peridem::Micromodulus::Conic;
  lmp->error->all(FLERR, "{}: unknown micromodulus '{}' (use constant or conic)", command, word);
  return peridem::Micromodulus::Constant;
}

const char *micromodulus_name(peridem::Micromodulus m)
{
  return m == peridem::Micromodulus::Conic ? "conic" : "constant";
}

} // namespace PERIDEM
