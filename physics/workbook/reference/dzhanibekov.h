// Reference: the Dzhanibekov (tennis-racket) case of docs/references.md §5,
// I = (3, 5, 9), L_B(0) = (0, 2, 0.01): almost a spin about the intermediate axis.
// L^2 = 4.0001, 2T = 4/5 + 0.0001/9, so L^2 - 2T I2 = 0.0001 - 5e-4/9 > 0 (the polhode
// circles axis 3, close to the separatrix); k^2 = 6.4 / (4 (4.0001 - 3 * 2T)) = 0.99996.
// The body flips: L_B,y changes sign at tau = 2 m K, i.e. every 2K/lambda, starting
// at t = K/lambda (tau0 = K, since omega1(0) = 0 and omega2(0) > 0).
// The exact solution is AsymmetricTop (asymmetric_top.h).
//
// Note: I3 = 9 > I1 + I2 = 8, which no real body has (the triangle inequality of
// principal moments); Euler's equations do not mind, but a box scene cannot have it.
#pragma once

#include "physics/workbook/reference/asymmetric_top.h"

namespace rbw::reference {

Vec3 dzhanibekovInertia();   // (3, 5, 9)
Vec3 dzhanibekovL0_B();      // (0, 2, 0.01)
AsymmetricTop dzhanibekov();

} // namespace rbw::reference
