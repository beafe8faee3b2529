/* brushedmetal: brushed metal from the micro model of parallel cylinders (thesis section 5.2,
 * ribs/brushed_metal.rib). The scratches run along dPdu (`brushing` "dPdv" turns them by 90
 * degrees): on a Disk they run in circles around its centre, as on the bottom of a pan (thesis
 * fig. 5.8). The model's cylinders lie along y of its frame, so the BRDF's x axis is across the
 * scratches. Kb scales the BRDF, Ka adds ambient light, Cs tints both. */
#include "brdf_lighting.h"

surface brushedmetal(string grid = "brushed_metal.grd";
                     float Kb = 1, Ka = 0;
                     string brushing = "dPdu")
{
    normal Nf = faceforward(normalize(N), I);
    vector scratches = brushing == "dPdv" ? dPdv : dPdu;
    vector across = Nf ^ scratches;
    Oi = Os;
    Ci = Os * Cs * (Kb * brdf_lighting(grid, Nf, -normalize(I), across) + Ka * ambient());
}
