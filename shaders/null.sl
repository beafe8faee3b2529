/* null: does nothing (RISpec: every shader type has a null shader). */
surface null()
{
}
