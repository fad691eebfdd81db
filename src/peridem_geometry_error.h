// Error type of the LAMMPS-independent PERIDEM geometry library.
//
// The geometry code (shapes, discretization, bonds) must not depend on LAMMPS,
// so it reports bad input by throwing this exception; the LAMMPS commands catch
// it and turn the message into a LAMMPS error (bad input gets a clear
// error).
#ifndef PERIDEM_GEOMETRY_ERROR_H
#define PERIDEM_GEOMETRY_ERROR_H

#include <stdexcept>
#include <string>

namespace peridem {

class GeometryError : public std::runtime_error {
 public:
  explicit GeometryError(const std::string &msg) : std::runtime_error(msg) {}
};

} // namespace peridem

#endif
