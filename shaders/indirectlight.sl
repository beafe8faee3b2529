/* indirectlight: the diffuse light other surfaces send, as an ambient light. It runs at the
   surface points (P, N, I) and gives E/π of the light arriving there by `samples` rays, their
   hits shaded by their own shaders; rays that miss see `environmentmap` ("" : black), looked
   up in world space. A matte surface (Ka · ambient()) then reflects Ka times that. */
light indirectlight(float intensity = 1; float samples = 64; float maxdist = 1e30;
                    string environmentmap = "") {
    normal Nf = faceforward(normalize(N), I);
    Cl = intensity * indirectdiffuse(P, Nf, samples, "maxdist", maxdist, "environmentmap",
                                     environmentmap);
}
