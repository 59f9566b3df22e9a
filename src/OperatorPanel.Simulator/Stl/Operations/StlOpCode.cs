namespace OperatorPanel.Simulator.Stl.Operations;

/// <summary>The executable operations; compares carry their width and relation in the op, so one code serves LDB=, AW&lt; and OD&gt;=.</summary>
internal enum StlOpCode
{
    Ld, Ldn, A, An, O, On, Not, Eu, Ed, Lps, Lrd, Lpp, Ald, Old, Assign, Set, Reset,
    CmpLd, CmpA, CmpO,
    MovB, MovW, MovD, Bmb, Bmw, Swap,
    AddI, SubI, MulI, DivI, AddD, SubD, MulD, DivD,
    IncB, IncW, IncD, DecB, DecW, DecD,
    Bti, Itb, Itd, Dti,
    AndB, OrB, XorB, InvB, AndW, OrW, XorW, InvW, AndD, OrD, XorD, InvD,
    Slb, Srb, Slw, Srw, Sld, Srd,
    Ath, Hta,
    For, Next, Jmp, Lbl, Call, Cret, Ret, Creti, Reti, End, Mend, Nop,
    Atch, Dtch, Eni, Disi, Rcv, Xmt,
    Ton, Tonr, Tof, Ctu, Ctd, Ctud,
    Ldi, Ldni, Ai, Ani, Oi, Oni, AssignI, SetI, ResetI, Bir, Biw, Aeno,
    Mul, Div, AddR, SubR, MulR, DivR, Sqrt, Ln, Exp, Sin, Cos, Tan,
    CmpRLd, CmpRA, CmpRO,
    Dtr, Round, Trunc, Bcdi, Ibcd, Deco, Enco, Seg, Ita, Dta, Rta,
    MovR, Bmd, Rlb, Rrb, Rlw, Rrw, Rld, Rrd, Shrb,
    Att, Fifo, Lifo, Fnd, Fill,
    Lscr, Scrt, Scre, Cscre, Stop, Wdr, Todr, Todw, Lds,
    Hdef, Hsc, Pls,
}
