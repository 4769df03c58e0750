// placeholder until the view library lands
