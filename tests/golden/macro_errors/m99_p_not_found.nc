(M99 P to a sequence number the caller does not have: alarm 78)
M98 P8400
M30
O8400
M99 P77
