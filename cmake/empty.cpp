// Every stage library lists this file so that a stage whose sources are all
// headers still forms a library target. It defines nothing.
