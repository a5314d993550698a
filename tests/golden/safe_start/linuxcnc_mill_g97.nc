( LinuxCNC: safe-start and tool-change blocks as CAM posts write them for a Fanuc )
( machining centre: G97 [constant surface speed cancel, group 13 on the )
( M series] is accepted and changes nothing on a mill: the spindle runs at S )
( in rpm. The block order is the posts': safe start, tool change, G54 and )
( the spindle, then G43 H. )


G90 G94 G17 G49 G40 G80
G21
G28 G91 Z0.
G90
T1 M06
G97 S5000 M03
G54 G00 X10. Y20.
G43 Z50. H01
G00 Z10.
G28 G91 Z0.
G90
M30

