/* A diffuse surface that also mirrors part of what it sees. Its colour multiplies the mirrored
 * light too, so a reflection is light that met two surfaces: the two-bounce products l r1 r2 of
 * thesis ch. 6, which a colour representation must keep (docs/spectral.md, docs/gallery.md). */
surface mattemirror(float Kd = 0.6; float Kr = 0.4) {
    normal Nf = faceforward(normalize(N), I);
    Ci = Cs * (Kd * diffuse(Nf) + Kr * trace(P, reflect(normalize(I), Nf)));
    Oi = 1;
}
