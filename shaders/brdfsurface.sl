/* brdfsurface: a surface whose reflection is a measured BRDF, read from the .grd file `grid`
 * (thesis Appendix C.4). Kb scales the BRDF, Ka adds ambient light, Cs tints both.
 * The grid's anisotropy direction D (the x axis of the frame the micro geometry was modelled in)
 * follows `orientation`: "dPdu" or "dPdv" (the surface's parametric directions), or "direction"
 * for the vector `direction` (in shader space). Isotropic grids ignore it. */
#include "brdf_lighting.h"

surface brdfsurface(string grid = "";
                    float Kb = 1, Ka = 0;
                    string orientation = "dPdu";
                    vector direction = vector "shader" (1, 0, 0))
{
    normal Nf = faceforward(normalize(N), I);
    vector D = dPdu;
    if (orientation == "dPdv")
        D = dPdv;
    else if (orientation == "direction")
        D = direction;
    Oi = Os;
    Ci = Os * Cs * (Kb * brdf_lighting(grid, Nf, -normalize(I), D) + Ka * ambient());
}
