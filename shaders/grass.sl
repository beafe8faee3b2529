/* grass: a lawn seen from far enough that single blades are not resolved, shaded with the BRDF
 * simulated from a micro model of grass blades (thesis section 5.3; ribs/grass.rib, or
 * ribs/grass_mowed.rib for mowed grass, which leans one way and is anisotropic). `angle` turns
 * the mowing direction about the normal from dPdu, in degrees: stripes mowed in opposite
 * directions are patches whose angles differ by 180. brdf() puts the micro model's x axis along
 * the turned dPdu, and the mowed blades lean along its y, so a lawn seen along dPdu shows its
 * mowing with angles 90 and 270 (thesis fig. 5.22, ribs/fig5_22_mowed.rib). Kb scales the
 * BRDF, Ka adds ambient light, Cs tints both (the simulated colour is already green). */
#include "brdf_lighting.h"

surface grass(string grid = "grass.grd";
              float Kb = 1, Ka = 0, angle = 0)
{
    normal Nf = faceforward(normalize(N), I);
    vector D = vector rotate(point dPdu, radians(angle), point 0, point Nf);
    Oi = Os;
    Ci = Os * Cs * (Kb * brdf_lighting(grid, Nf, -normalize(I), D) + Ka * ambient());
}
