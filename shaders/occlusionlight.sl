/* occlusionlight: ambient light dimmed by ambient occlusion. As an ambient light (no
   illuminate) it runs at the surface points, with their P, N and I; ambient() sums it.
   Cl = intensity * lightcolor * (1 - occlusion), the occlusion of `samples` cosine-distributed
   rays up to `maxdist` (docs/shading-language.md, Ray-traced built-ins). */
light occlusionlight(float intensity = 1; color lightcolor = 1; float samples = 64;
                     float maxdist = 1e30) {
    normal Nf = faceforward(normalize(N), I);
    Cl = intensity * lightcolor * (1 - occlusion(P, Nf, samples, "maxdist", maxdist));
}
