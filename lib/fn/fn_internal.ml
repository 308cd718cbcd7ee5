let count = 79
let arity _ = 3
let name k = Printf.sprintf "internal%d" k
let make ~noise_generator:_ _ = None
