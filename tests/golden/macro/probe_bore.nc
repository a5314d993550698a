(Runs the example examples/macros/O0100.nc: a bore centre found with the)
(probing macros O8810 and O8814 on the built-in mill3, scene bore.scene.toml)
M98 P100
