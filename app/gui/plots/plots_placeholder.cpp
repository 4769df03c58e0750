// placeholder until the plots library lands
