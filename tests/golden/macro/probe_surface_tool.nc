(Runs the example examples/macros/O0101.nc: the top face sets G54 Z with)
(O8811, then O8801 measures a 60 mm tool on the setter into offset 12)
M98 P101
