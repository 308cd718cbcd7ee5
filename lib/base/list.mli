(** OCaml's [List], as the whole library sees it, with every function safe on lists of millions of
    elements: [map], [mapi], [map2], [append], [concat], [flatten], [concat_map], [fold_right],
    [fold_right2], [split] and [combine] use a bounded stack (OCaml 4.13's do not), applying their
    function in OCaml's order. Everything else is [Stdlib.List]'s. *)

include module type of struct
  include Stdlib.List
end
