using System.Collections.Frozen;
using static OperatorPanel.Simulator.Stl.StlOperandType;

namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// The mnemonics the simulator executes and the operands each takes (/work/briefs/stl-dialect.md, "Instructions").
/// Compares (LDB=, AW&lt;&gt;, OD&gt;= ...) are read by <see cref="TryCompare"/> instead of listed one by one.
/// </summary>
internal static class StlInstructionSet
{
    private static readonly FrozenDictionary<string, (StlOpCode Code, StlOperandType[] Operands)> Table =
        new Dictionary<string, (StlOpCode, StlOperandType[])>
        {
            ["LD"] = (StlOpCode.Ld, [BitIn]),
            ["LDN"] = (StlOpCode.Ldn, [BitIn]),
            ["A"] = (StlOpCode.A, [BitIn]),
            ["AN"] = (StlOpCode.An, [BitIn]),
            ["O"] = (StlOpCode.O, [BitIn]),
            ["ON"] = (StlOpCode.On, [BitIn]),
            ["NOT"] = (StlOpCode.Not, []),
            ["EU"] = (StlOpCode.Eu, []),
            ["ED"] = (StlOpCode.Ed, []),
            ["LPS"] = (StlOpCode.Lps, []),
            ["LRD"] = (StlOpCode.Lrd, []),
            ["LPP"] = (StlOpCode.Lpp, []),
            ["ALD"] = (StlOpCode.Ald, []),
            ["OLD"] = (StlOpCode.Old, []),
            ["="] = (StlOpCode.Assign, [BitOut]),
            ["S"] = (StlOpCode.Set, [BitOut, ByteIn]),
            ["R"] = (StlOpCode.Reset, [BitOut, ByteIn]),
            ["MOVB"] = (StlOpCode.MovB, [ByteIn, ByteOut]),
            ["MOVW"] = (StlOpCode.MovW, [WordIn, WordOut]),
            ["MOVD"] = (StlOpCode.MovD, [DWordIn, DWordOut]),
            ["BMB"] = (StlOpCode.Bmb, [ByteArea, ByteArea, ByteIn]),
            ["BMW"] = (StlOpCode.Bmw, [WordArea, WordArea, ByteIn]),
            ["SWAP"] = (StlOpCode.Swap, [WordOut]),
            ["+I"] = (StlOpCode.AddI, [WordIn, WordOut]),
            ["-I"] = (StlOpCode.SubI, [WordIn, WordOut]),
            ["*I"] = (StlOpCode.MulI, [WordIn, WordOut]),
            ["/I"] = (StlOpCode.DivI, [WordIn, WordOut]),
            ["+D"] = (StlOpCode.AddD, [DWordIn, DWordOut]),
            ["-D"] = (StlOpCode.SubD, [DWordIn, DWordOut]),
            ["*D"] = (StlOpCode.MulD, [DWordIn, DWordOut]),
            ["/D"] = (StlOpCode.DivD, [DWordIn, DWordOut]),
            ["INCB"] = (StlOpCode.IncB, [ByteOut]),
            ["INCW"] = (StlOpCode.IncW, [WordOut]),
            ["INCD"] = (StlOpCode.IncD, [DWordOut]),
            ["DECB"] = (StlOpCode.DecB, [ByteOut]),
            ["DECW"] = (StlOpCode.DecW, [WordOut]),
            ["DECD"] = (StlOpCode.DecD, [DWordOut]),
            ["BTI"] = (StlOpCode.Bti, [ByteIn, WordOut]),
            ["ITB"] = (StlOpCode.Itb, [WordIn, ByteOut]),
            ["ITD"] = (StlOpCode.Itd, [WordIn, DWordOut]),
            ["DTI"] = (StlOpCode.Dti, [DWordIn, WordOut]),
            ["ANDB"] = (StlOpCode.AndB, [ByteIn, ByteOut]),
            ["ORB"] = (StlOpCode.OrB, [ByteIn, ByteOut]),
            ["XORB"] = (StlOpCode.XorB, [ByteIn, ByteOut]),
            ["INVB"] = (StlOpCode.InvB, [ByteOut]),
            ["ANDW"] = (StlOpCode.AndW, [WordIn, WordOut]),
            ["ORW"] = (StlOpCode.OrW, [WordIn, WordOut]),
            ["XORW"] = (StlOpCode.XorW, [WordIn, WordOut]),
            ["INVW"] = (StlOpCode.InvW, [WordOut]),
            ["ANDD"] = (StlOpCode.AndD, [DWordIn, DWordOut]),
            ["ORD"] = (StlOpCode.OrD, [DWordIn, DWordOut]),
            ["XORD"] = (StlOpCode.XorD, [DWordIn, DWordOut]),
            ["INVD"] = (StlOpCode.InvD, [DWordOut]),
            ["SLB"] = (StlOpCode.Slb, [ByteOut, ByteIn]),
            ["SRB"] = (StlOpCode.Srb, [ByteOut, ByteIn]),
            ["SLW"] = (StlOpCode.Slw, [WordOut, ByteIn]),
            ["SRW"] = (StlOpCode.Srw, [WordOut, ByteIn]),
            ["SLD"] = (StlOpCode.Sld, [DWordOut, ByteIn]),
            ["SRD"] = (StlOpCode.Srd, [DWordOut, ByteIn]),
            ["ATH"] = (StlOpCode.Ath, [ByteArea, ByteArea, ByteIn]),
            ["HTA"] = (StlOpCode.Hta, [ByteArea, ByteArea, ByteIn]),
            ["FOR"] = (StlOpCode.For, [WordOut, WordIn, WordIn]),
            ["NEXT"] = (StlOpCode.Next, []),
            ["JMP"] = (StlOpCode.Jmp, [Label]),
            ["LBL"] = (StlOpCode.Lbl, [Label]),
            ["CALL"] = (StlOpCode.Call, [Block]),
            ["CRET"] = (StlOpCode.Cret, []),
            ["RET"] = (StlOpCode.Ret, []),
            ["CRETI"] = (StlOpCode.Creti, []),
            ["RETI"] = (StlOpCode.Reti, []),
            ["END"] = (StlOpCode.End, []),
            ["MEND"] = (StlOpCode.Mend, []),
            ["NOP"] = (StlOpCode.Nop, [ByteIn]),
            ["ATCH"] = (StlOpCode.Atch, [Block, Event]),
            ["DTCH"] = (StlOpCode.Dtch, [Event]),
            ["ENI"] = (StlOpCode.Eni, []),
            ["DISI"] = (StlOpCode.Disi, []),
            ["RCV"] = (StlOpCode.Rcv, [ByteArea, Port]),
            ["XMT"] = (StlOpCode.Xmt, [ByteArea, Port]),
            ["TON"] = (StlOpCode.Ton, [StlOperandType.Timer, WordIn]),
            ["TONR"] = (StlOpCode.Tonr, [StlOperandType.Timer, WordIn]),
            ["TOF"] = (StlOpCode.Tof, [StlOperandType.Timer, WordIn]),
            ["CTU"] = (StlOpCode.Ctu, [Counter, WordIn]),
            ["CTD"] = (StlOpCode.Ctd, [Counter, WordIn]),
            ["CTUD"] = (StlOpCode.Ctud, [Counter, WordIn]),
            ["LDI"] = (StlOpCode.Ldi, [BitIn]),
            ["LDNI"] = (StlOpCode.Ldni, [BitIn]),
            ["AI"] = (StlOpCode.Ai, [BitIn]),
            ["ANI"] = (StlOpCode.Ani, [BitIn]),
            ["OI"] = (StlOpCode.Oi, [BitIn]),
            ["ONI"] = (StlOpCode.Oni, [BitIn]),
            ["=I"] = (StlOpCode.AssignI, [BitOut]),
            ["SI"] = (StlOpCode.SetI, [BitOut, ByteIn]),
            ["RI"] = (StlOpCode.ResetI, [BitOut, ByteIn]),
            ["BIR"] = (StlOpCode.Bir, [ByteIn, ByteOut]),
            ["BIW"] = (StlOpCode.Biw, [ByteIn, ByteOut]),
            ["AENO"] = (StlOpCode.Aeno, []),
            ["MUL"] = (StlOpCode.Mul, [WordIn, DWordOut]),
            ["DIV"] = (StlOpCode.Div, [WordIn, DWordOut]),
            ["+R"] = (StlOpCode.AddR, [DWordIn, DWordOut]),
            ["-R"] = (StlOpCode.SubR, [DWordIn, DWordOut]),
            ["*R"] = (StlOpCode.MulR, [DWordIn, DWordOut]),
            ["/R"] = (StlOpCode.DivR, [DWordIn, DWordOut]),
            ["SQRT"] = (StlOpCode.Sqrt, [DWordIn, DWordOut]),
            ["LN"] = (StlOpCode.Ln, [DWordIn, DWordOut]),
            ["EXP"] = (StlOpCode.Exp, [DWordIn, DWordOut]),
            ["SIN"] = (StlOpCode.Sin, [DWordIn, DWordOut]),
            ["COS"] = (StlOpCode.Cos, [DWordIn, DWordOut]),
            ["TAN"] = (StlOpCode.Tan, [DWordIn, DWordOut]),
            ["DTR"] = (StlOpCode.Dtr, [DWordIn, DWordOut]),
            ["ROUND"] = (StlOpCode.Round, [DWordIn, DWordOut]),
            ["TRUNC"] = (StlOpCode.Trunc, [DWordIn, DWordOut]),
            ["BCDI"] = (StlOpCode.Bcdi, [WordOut]),
            ["IBCD"] = (StlOpCode.Ibcd, [WordOut]),
            ["DECO"] = (StlOpCode.Deco, [ByteIn, WordOut]),
            ["ENCO"] = (StlOpCode.Enco, [WordIn, ByteOut]),
            ["SEG"] = (StlOpCode.Seg, [ByteIn, ByteOut]),
            ["ITA"] = (StlOpCode.Ita, [WordIn, ByteArea, ByteIn]),
            ["DTA"] = (StlOpCode.Dta, [DWordIn, ByteArea, ByteIn]),
            ["RTA"] = (StlOpCode.Rta, [DWordIn, ByteArea, ByteIn]),
            ["MOVR"] = (StlOpCode.MovR, [DWordIn, DWordOut]),
            ["BMD"] = (StlOpCode.Bmd, [DWordArea, DWordArea, ByteIn]),
            ["RLB"] = (StlOpCode.Rlb, [ByteOut, ByteIn]),
            ["RRB"] = (StlOpCode.Rrb, [ByteOut, ByteIn]),
            ["RLW"] = (StlOpCode.Rlw, [WordOut, ByteIn]),
            ["RRW"] = (StlOpCode.Rrw, [WordOut, ByteIn]),
            ["RLD"] = (StlOpCode.Rld, [DWordOut, ByteIn]),
            ["RRD"] = (StlOpCode.Rrd, [DWordOut, ByteIn]),
            ["SHRB"] = (StlOpCode.Shrb, [BitIn, BitOut, SignedByteIn]),
            ["ATT"] = (StlOpCode.Att, [WordIn, WordArea]),
            ["FIFO"] = (StlOpCode.Fifo, [WordArea, WordOut]),
            ["LIFO"] = (StlOpCode.Lifo, [WordArea, WordOut]),
            ["FND="] = (StlOpCode.Fnd, [WordArea, WordIn, WordOut]),
            ["FND<>"] = (StlOpCode.Fnd, [WordArea, WordIn, WordOut]),
            ["FND<"] = (StlOpCode.Fnd, [WordArea, WordIn, WordOut]),
            ["FND>"] = (StlOpCode.Fnd, [WordArea, WordIn, WordOut]),
            ["FILL"] = (StlOpCode.Fill, [WordIn, WordArea, ByteIn]),
            ["LSCR"] = (StlOpCode.Lscr, [BitIn]),
            ["SCRT"] = (StlOpCode.Scrt, [BitOut]),
            ["SCRE"] = (StlOpCode.Scre, []),
            ["CSCRE"] = (StlOpCode.Cscre, []),
            ["STOP"] = (StlOpCode.Stop, []),
            ["WDR"] = (StlOpCode.Wdr, []),
            ["TODR"] = (StlOpCode.Todr, [ByteArea]),
            ["TODW"] = (StlOpCode.Todw, [ByteArea]),
        }.ToFrozenDictionary(StringComparer.Ordinal);

    /// <summary>Every mnemonic of the table (compares are read by form, not listed).</summary>
    public static IEnumerable<string> Mnemonics => Table.Keys;

    public static bool TryGet(string mnemonic, out StlOpCode code, out StlOperandType[] operands)
    {
        if (Table.TryGetValue(mnemonic, out var entry))
        {
            (code, operands) = entry;
            return true;
        }

        return TryCompare(mnemonic, out code, out operands);
    }

    /// <summary>LDB=, AW&lt;&gt;, OD&gt;=: form (LD/A/O), width (B unsigned, W and D signed), relation.</summary>
    private static bool TryCompare(string mnemonic, out StlOpCode code, out StlOperandType[] operands)
    {
        (code, var rest) = mnemonic.StartsWith("LD", StringComparison.Ordinal) ? (StlOpCode.CmpLd, mnemonic[2..])
            : mnemonic.StartsWith('A') ? (StlOpCode.CmpA, mnemonic[1..])
            : mnemonic.StartsWith('O') ? (StlOpCode.CmpO, mnemonic[1..])
            : (StlOpCode.Nop, string.Empty);
        operands = rest.Length > 1 ? rest[0] switch
        {
            'B' => [ByteIn, ByteIn],
            'W' => [WordIn, WordIn],
            'D' or 'R' => [DWordIn, DWordIn],
            _ => [],
        } : [];
        if (rest.Length > 1 && rest[0] == 'R')
        {
            code = code switch
            {
                StlOpCode.CmpLd => StlOpCode.CmpRLd,
                StlOpCode.CmpA => StlOpCode.CmpRA,
                _ => StlOpCode.CmpRO,
            };
        }

        return operands.Length == 2 && RelationOf(rest[1..]) is not null;
    }

    /// <summary>The relation of a compare mnemonic's tail: 0 =, 1 &lt;&gt;, 2 &lt;, 3 &lt;=, 4 &gt;, 5 &gt;=.</summary>
    public static int? RelationOf(string relation) => relation switch
    {
        "=" or "==" => 0,
        "<>" => 1,
        "<" => 2,
        "<=" => 3,
        ">" => 4,
        ">=" => 5,
        _ => null,
    };
}
