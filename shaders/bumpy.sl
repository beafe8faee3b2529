/* bumpy: moves the surface along its normal by Km times a texture's value. A ray tracer does
   not move the geometry: only the shading normal changes (bump mapping). RISpec's parameter
   table calls the scale "amplitude" while its listing says Km; both are accepted. (s, t) are
   passed explicitly: the compiler gives texture("name") no s and t unless the shader names
   them. */
displacement bumpy(float Km = 1, amplitude = 1; string texturename = "")
{
    if (texturename != "") {
        float height = Km * amplitude * float texture(texturename, s, t);
        P += height * normalize(N);
        N = calculatenormal(P);
    }
}
