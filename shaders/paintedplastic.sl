/* paintedplastic: plastic whose base colour is multiplied by a texture map over (s, t). The
   coordinates are passed explicitly: the compiler gives texture("name") no s and t unless the
   shader names them. */
surface paintedplastic(float Ka = 1, Kd = .5, Ks = .5, roughness = .1;
                       color specularcolor = 1; string texturename = "")
{
    normal Nf = faceforward(normalize(N), I);
    vector V = -normalize(I);
    color base = Cs;
    if (texturename != "")
        base *= color texture(texturename, s, t);
    Oi = Os;
    Ci = Os * (base * (Ka * ambient() + Kd * diffuse(Nf)) +
               specularcolor * Ks * specular(Nf, V, roughness));
}
