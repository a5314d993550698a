%
O24 (O9819 BOSSES OUT OF TOLERANCE: H ON THE FEATURES' SIZE)
(The five bosses of o9819_bosses.scene.toml, 11.98 across against D12.:)
(#143 = -0.02, larger than H0.01: #148 = 1 and alarm 3088 OUT OF)
(TOLERANCE, with the results stored [#135 = 149.93, #138 = 11.98], their)
(copy at #185 = 149.93, #188 = 11.98, #193 = -0.02, #198 = 1, and G54 left)
(as it was [S1 not applied]: #5221 = -80, #5222 = 30.5.)
N10 G21 G90 G17 G40 G49 G80 G54
N20 #550=1.
N30 G53 G0 Z0
N40 G43 H20 G0 X150. Y-60.
N50 G65 P9810 Z15. F3000.
N60 G65 P9819 A18. B5. C50. D12. Z3. Q5. R5. H0.01 S1.
N70 G65 P9810 Z50.
N80 M30
%
