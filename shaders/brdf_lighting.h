/* brdf_lighting.h: the reflection of every light through a measured BRDF (a .grd from
 * `gonio brdf iopt`/`opt`), for the BRDF surface shaders. Nf is the front-facing unit normal,
 * V the unit direction towards the viewer, D the x axis of the frame the micro geometry was
 * modelled in (its direction of anisotropy; ignored by isotropic grids). */
color brdf_lighting(string grid; normal Nf; vector V; vector D)
{
    color C = 0;
    illuminance (P, Nf, PI / 2) {
        vector Ln = normalize(L);
        C += Cl * brdf(grid, Nf, V, Ln, D) * (Nf . Ln);
    }
    return C;
}
