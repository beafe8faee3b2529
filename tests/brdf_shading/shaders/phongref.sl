/* phongref: the analytic normalised Phong BRDF ks·(n+2)/(2π)·cosⁿα (α between the viewer and
 * the light's mirror direction; DESIGN.md, thesis eq. 3.17), lit like brdfsurface, as the
 * reference the measured Phong plane must reproduce. */
surface phongref(float Ks = 1, exponent = 25)
{
    normal Nf = faceforward(normalize(N), I);
    vector V = -normalize(I);
    color C = 0;
    illuminance (P, Nf, PI / 2) {
        vector Ln = normalize(L);
        vector mirror = 2 * (Nf . Ln) * Nf - Ln;
        float cosAlpha = max(0, mirror . V);
        C += Cl * Ks * (exponent + 2) / (2 * PI) * pow(cosAlpha, exponent) * (Nf . Ln);
    }
    Oi = Os;
    Ci = Os * Cs * C;
}
