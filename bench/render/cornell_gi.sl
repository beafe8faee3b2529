/* cornell_gi: the surfaces of cornell_pixie.rib for Pixie's raytrace hider: direct light (the
 * light's own ray-traced visibility), one indirect diffuse ray per shaded point without the
 * irradiance cache ("maxerror" 0), and plastic's highlight where Ks > 0. The comparison's peer of
 * gonio's path tracer on cornell_pathtrace.rib (bench/render/run_cornell_pathtrace.sh). */
surface cornell_gi(float Kd = 0.75, Ks = 0, roughness = 0.1) {
    normal Nf = faceforward(normalize(N), I);
    color indirect = indirectdiffuse(P, Nf, 1, "maxerror", 0);
    Oi = Os;
    Ci = Os * (Cs * Kd * (diffuse(Nf) + indirect) +
               Ks * specular(Nf, -normalize(I), roughness));
}
