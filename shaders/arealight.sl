/* arealight: a uniform, one-sided emitter of radiance intensity * lightcolor, for
   AreaLightSource. The renderer runs it at points sampled on the light's surface (P, with N the
   emitting side's normal there) and weights each run's Cl by the area it stands for
   (docs/shading-language.md, Area lights), so Cl here is radiance times the cosine at the
   emitter over the squared distance: what one unit of area sends to the shaded point. */
light arealight(float intensity = 1; color lightcolor = 1)
{
    normal Nn = normalize(N);
    illuminate(P, Nn, PI / 2) {
        Cl = intensity * lightcolor * (Nn . normalize(L)) / (L . L);
    }
}
