using System.Collections.Frozen;
using OperatorPanel.Stl.Instructions;

namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// The mnemonics the simulator executes, each with its op code. The operands each takes come from the Core
/// <see cref="StlInstructionTable"/>, the one table from the manual; a mnemonic of the table without an op code here is
/// refused by name and line before the program runs. Compares (LDB=, AW&lt;&gt;, OD&gt;= ...) map by form.
/// </summary>
internal static class StlInstructionSet
{
    private static readonly FrozenDictionary<string, StlOpCode> Codes =
        new Dictionary<string, StlOpCode>
        {
            ["LD"] = StlOpCode.Ld,
            ["LDN"] = StlOpCode.Ldn,
            ["A"] = StlOpCode.A,
            ["AN"] = StlOpCode.An,
            ["O"] = StlOpCode.O,
            ["ON"] = StlOpCode.On,
            ["NOT"] = StlOpCode.Not,
            ["EU"] = StlOpCode.Eu,
            ["ED"] = StlOpCode.Ed,
            ["LPS"] = StlOpCode.Lps,
            ["LRD"] = StlOpCode.Lrd,
            ["LPP"] = StlOpCode.Lpp,
            ["ALD"] = StlOpCode.Ald,
            ["OLD"] = StlOpCode.Old,
            ["="] = StlOpCode.Assign,
            ["S"] = StlOpCode.Set,
            ["R"] = StlOpCode.Reset,
            ["MOVB"] = StlOpCode.MovB,
            ["MOVW"] = StlOpCode.MovW,
            ["MOVD"] = StlOpCode.MovD,
            ["BMB"] = StlOpCode.Bmb,
            ["BMW"] = StlOpCode.Bmw,
            ["SWAP"] = StlOpCode.Swap,
            ["+I"] = StlOpCode.AddI,
            ["-I"] = StlOpCode.SubI,
            ["*I"] = StlOpCode.MulI,
            ["/I"] = StlOpCode.DivI,
            ["+D"] = StlOpCode.AddD,
            ["-D"] = StlOpCode.SubD,
            ["*D"] = StlOpCode.MulD,
            ["/D"] = StlOpCode.DivD,
            ["INCB"] = StlOpCode.IncB,
            ["INCW"] = StlOpCode.IncW,
            ["INCD"] = StlOpCode.IncD,
            ["DECB"] = StlOpCode.DecB,
            ["DECW"] = StlOpCode.DecW,
            ["DECD"] = StlOpCode.DecD,
            ["BTI"] = StlOpCode.Bti,
            ["ITB"] = StlOpCode.Itb,
            ["ITD"] = StlOpCode.Itd,
            ["DTI"] = StlOpCode.Dti,
            ["ANDB"] = StlOpCode.AndB,
            ["ORB"] = StlOpCode.OrB,
            ["XORB"] = StlOpCode.XorB,
            ["INVB"] = StlOpCode.InvB,
            ["ANDW"] = StlOpCode.AndW,
            ["ORW"] = StlOpCode.OrW,
            ["XORW"] = StlOpCode.XorW,
            ["INVW"] = StlOpCode.InvW,
            ["ANDD"] = StlOpCode.AndD,
            ["ORD"] = StlOpCode.OrD,
            ["XORD"] = StlOpCode.XorD,
            ["INVD"] = StlOpCode.InvD,
            ["SLB"] = StlOpCode.Slb,
            ["SRB"] = StlOpCode.Srb,
            ["SLW"] = StlOpCode.Slw,
            ["SRW"] = StlOpCode.Srw,
            ["SLD"] = StlOpCode.Sld,
            ["SRD"] = StlOpCode.Srd,
            ["ATH"] = StlOpCode.Ath,
            ["HTA"] = StlOpCode.Hta,
            ["FOR"] = StlOpCode.For,
            ["NEXT"] = StlOpCode.Next,
            ["JMP"] = StlOpCode.Jmp,
            ["LBL"] = StlOpCode.Lbl,
            ["CALL"] = StlOpCode.Call,
            ["CRET"] = StlOpCode.Cret,
            ["RET"] = StlOpCode.Ret,
            ["CRETI"] = StlOpCode.Creti,
            ["RETI"] = StlOpCode.Reti,
            ["END"] = StlOpCode.End,
            ["MEND"] = StlOpCode.Mend,
            ["NOP"] = StlOpCode.Nop,
            ["ATCH"] = StlOpCode.Atch,
            ["DTCH"] = StlOpCode.Dtch,
            ["ENI"] = StlOpCode.Eni,
            ["DISI"] = StlOpCode.Disi,
            ["RCV"] = StlOpCode.Rcv,
            ["XMT"] = StlOpCode.Xmt,
            ["TON"] = StlOpCode.Ton,
            ["TONR"] = StlOpCode.Tonr,
            ["TOF"] = StlOpCode.Tof,
            ["CTU"] = StlOpCode.Ctu,
            ["CTD"] = StlOpCode.Ctd,
            ["CTUD"] = StlOpCode.Ctud,
            ["LDI"] = StlOpCode.Ldi,
            ["LDNI"] = StlOpCode.Ldni,
            ["AI"] = StlOpCode.Ai,
            ["ANI"] = StlOpCode.Ani,
            ["OI"] = StlOpCode.Oi,
            ["ONI"] = StlOpCode.Oni,
            ["=I"] = StlOpCode.AssignI,
            ["SI"] = StlOpCode.SetI,
            ["RI"] = StlOpCode.ResetI,
            ["BIR"] = StlOpCode.Bir,
            ["BIW"] = StlOpCode.Biw,
            ["AENO"] = StlOpCode.Aeno,
            ["MUL"] = StlOpCode.Mul,
            ["DIV"] = StlOpCode.Div,
            ["+R"] = StlOpCode.AddR,
            ["-R"] = StlOpCode.SubR,
            ["*R"] = StlOpCode.MulR,
            ["/R"] = StlOpCode.DivR,
            ["SQRT"] = StlOpCode.Sqrt,
            ["LN"] = StlOpCode.Ln,
            ["EXP"] = StlOpCode.Exp,
            ["SIN"] = StlOpCode.Sin,
            ["COS"] = StlOpCode.Cos,
            ["TAN"] = StlOpCode.Tan,
            ["DTR"] = StlOpCode.Dtr,
            ["ROUND"] = StlOpCode.Round,
            ["TRUNC"] = StlOpCode.Trunc,
            ["BCDI"] = StlOpCode.Bcdi,
            ["IBCD"] = StlOpCode.Ibcd,
            ["DECO"] = StlOpCode.Deco,
            ["ENCO"] = StlOpCode.Enco,
            ["SEG"] = StlOpCode.Seg,
            ["ITA"] = StlOpCode.Ita,
            ["DTA"] = StlOpCode.Dta,
            ["RTA"] = StlOpCode.Rta,
            ["MOVR"] = StlOpCode.MovR,
            ["BMD"] = StlOpCode.Bmd,
            ["RLB"] = StlOpCode.Rlb,
            ["RRB"] = StlOpCode.Rrb,
            ["RLW"] = StlOpCode.Rlw,
            ["RRW"] = StlOpCode.Rrw,
            ["RLD"] = StlOpCode.Rld,
            ["RRD"] = StlOpCode.Rrd,
            ["SHRB"] = StlOpCode.Shrb,
            ["ATT"] = StlOpCode.Att,
            ["FIFO"] = StlOpCode.Fifo,
            ["LIFO"] = StlOpCode.Lifo,
            ["FND="] = StlOpCode.Fnd,
            ["FND<>"] = StlOpCode.Fnd,
            ["FND<"] = StlOpCode.Fnd,
            ["FND>"] = StlOpCode.Fnd,
            ["FILL"] = StlOpCode.Fill,
            ["LSCR"] = StlOpCode.Lscr,
            ["SCRT"] = StlOpCode.Scrt,
            ["SCRE"] = StlOpCode.Scre,
            ["CSCRE"] = StlOpCode.Cscre,
            ["STOP"] = StlOpCode.Stop,
            ["WDR"] = StlOpCode.Wdr,
            ["TODR"] = StlOpCode.Todr,
            ["TODW"] = StlOpCode.Todw,
            ["LDS"] = StlOpCode.Lds,
        }.ToFrozenDictionary(StringComparer.Ordinal);

    /// <summary>Every mnemonic with an op code (compares map by form and are not listed).</summary>
    public static IEnumerable<string> Mnemonics => Codes.Keys;

    /// <summary>The op code and operand types of a mnemonic the simulator executes; false for any other.</summary>
    public static bool TryGet(string mnemonic, out StlOpCode code, out StlOperandType[] operands)
    {
        operands = [];
        if (!StlInstructionTable.TryGet(mnemonic, out var spec) || !TryCode(spec, out code))
        {
            code = default;
            return false;
        }

        operands = [.. spec.Operands.Select(StlOperandTypes.Of)];
        return true;
    }

    /// <summary>The relation of a compare mnemonic's tail: 0 =, 1 &lt;&gt;, 2 &lt;, 3 &lt;=, 4 &gt;, 5 &gt;=.</summary>
    public static int? RelationOf(string relation)
    {
        var index = Array.IndexOf(StlInstructionTable.Relations, relation);
        return index < 0 ? null : index;
    }

    /// <summary>Compares of bytes, words, double words and reals map by form (LD, A, O); string compares are not executed yet.</summary>
    private static bool TryCode(StlInstructionSpec spec, out StlOpCode code)
    {
        if (!spec.IsCompare)
        {
            return Codes.TryGetValue(spec.Mnemonic, out code);
        }

        var form = spec.Mnemonic.StartsWith("LD", StringComparison.Ordinal) ? "LD" : spec.Mnemonic[..1];
        var real = spec.Mnemonic[form.Length] == 'R';
        code = (form, real) switch
        {
            ("LD", false) => StlOpCode.CmpLd,
            ("A", false) => StlOpCode.CmpA,
            (_, false) => StlOpCode.CmpO,
            ("LD", true) => StlOpCode.CmpRLd,
            ("A", true) => StlOpCode.CmpRA,
            (_, true) => StlOpCode.CmpRO,
        };
        return spec.Mnemonic[form.Length] is 'B' or 'W' or 'D' or 'R';
    }
}
