( A setting given a negative value is error:4 [settings_store_global_setting]. )
( $27 is the homing pull-off, in mm. )
$27=-1
M2
