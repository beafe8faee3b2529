/* shinymetal: metal plus a mirror reflection read from an environment map (in world space). */
surface shinymetal(float Ka = 1, Ks = 1, Kr = 1, roughness = .1; string texturename = "")
{
    normal Nf = faceforward(normalize(N), I);
    vector V = -normalize(I);
    color reflected = 0;
    if (texturename != "") {
        vector D = vtransform("world", reflect(I, Nf));
        reflected = color environment(texturename, D);
    }
    Oi = Os;
    Ci = Os * Cs * (Ka * ambient() + Ks * specular(Nf, V, roughness) + Kr * reflected);
}
