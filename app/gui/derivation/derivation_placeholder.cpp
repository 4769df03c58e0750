// placeholder until the derivation library lands
