/* shadowdistant: distantlight whose light is stopped by a shadow map (an orthographic depth
   render from the light), with shadowspot's filter parameters. */
light shadowdistant(float intensity = 1; color lightcolor = 1;
                    point from = point "shader" (0, 0, 0); point to = point "shader" (0, 0, 1);
                    string shadowname = ""; float samples = 16, blur = 0, width = 1, bias = -1)
{
    solar(to - from, 0) {
        Cl = intensity * lightcolor;
        if (shadowname != "")
            Cl *= 1 - shadow(shadowname, Ps, "samples", samples, "blur", blur, "width", width,
                             "bias", bias);
    }
}
