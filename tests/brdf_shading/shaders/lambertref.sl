/* lambertref: the analytic Lambert BRDF Kd/π (1/sr), lit like brdfsurface, as the reference
 * the measured Lambert plane must reproduce. */
surface lambertref(float Kd = 1)
{
    normal Nf = faceforward(normalize(N), I);
    color C = 0;
    illuminance (P, Nf, PI / 2) {
        vector Ln = normalize(L);
        C += Cl * (Kd / PI) * (Nf . Ln);
    }
    Oi = Os;
    Ci = Os * Cs * C;
}
