(Any program: the machine type is refused)
M30
