(Any program: the machine file is refused)
M30
