(** POV-Ray's constant folding of function bodies (optimise_expr in fnsyntax.cpp), rule for rule,
    because it changes values: folding works on one precedence chain at a time, and so it can join
    constants that the written order keeps apart.

    - A negated constant becomes a constant.
    - In a chain, [- c] (c a constant) becomes [+ (−c)]; then two neighbouring constant operands
      are joined with the operator between them, and the result replaces the left one. [*] and [/]
      are joined only while nothing to their left in the chain uses a variable ([x * 2 * 3] stays;
      [2 * 3 * x] is [6 * x]). The left operand keeps the operator in front of it, so
      [a - 2*3 + 4] is [a - 10], as in POV-Ray.
    - A chain reduced to one constant is that constant; a parenthesised expression never is.
    - [pow(a, b)] becomes a chain [a ^ b]; only the first argument of any other call is folded. *)

val optimise : Fn.expr -> Fn.expr
(** [optimise e] is [e] folded as POV-Ray folds it. *)

val has_var : Fn.expr -> bool
(** [has_var e] tells whether [e] reads a variable anywhere (calls included). *)

val truth : float -> float
(** [truth x] is 1 when [x] is not 0, else 0 (the VM's [tne]). *)
