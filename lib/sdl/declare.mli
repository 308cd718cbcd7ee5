(** Declarations (docs/povray-rules.md §11.3): the value of a #declare or a macro argument, arrays, and where
    a value is stored. *)

val parse_rvalue : ?store:(Value.t -> unit) -> ?name:string -> Reader.st -> Value.t * bool
(** [parse_rvalue ~store ~name st] reads a declarable value and whether a ';' should follow it
    ([name] is the identifier declared, which a function's body may not call). An array
    is passed to [store] as soon as its size is known, before its initialiser is looked for, so the
    directives read by that look see it. *)

val parse_index : Reader.st -> Value.array_v -> int
(** [parse_index st a] reads the subscripts of an element of [a] as a row-major index. *)

val assign : ?current:Value.t ref Reader.Names.t list -> Reader.st -> local:bool -> string -> Value.t -> unit
(** [assign st ~local name v] stores [v] as #local or #declare do; a new #local goes to the head of
    [current] (the tables when the declaration began), by default the current table. *)

val parse_declare : Reader.st -> local:bool -> Loc.t -> unit
(** [parse_declare st ~local loc] reads and runs a #declare or #local. *)

val special_function : Reader.st -> string -> Loc.t -> Fn.t option
(** [special_function st kw loc] reads the function [kw] starts, the keyword next: a pigment,
    transform, spline or pattern function (function.cpp); None for another keyword. *)
