namespace OperatorPanel.Stl.Checks;

/// <summary>The refusals of <see cref="AwlProgramCheck"/>: what Micro/WIN refuses. Never renumber or reuse one.</summary>
public static class AwlCheckIds
{
    /// <summary>A mnemonic that is not a SIMATIC STL instruction of the S7-200 (SHLW, MOVX).</summary>
    public const string UnknownInstruction = "AWL001";

    /// <summary>MEND, RET or RETI written out: Micro/WIN adds them at the end of each block itself.</summary>
    public const string ImplicitBlockEnd = "AWL002";

    /// <summary>A compare whose relation STL does not write: LDW==, AB=&lt; (STL has =, &lt;&gt;, &lt;, &lt;=, &gt;, &gt;=).</summary>
    public const string CompareRelation = "AWL003";

    /// <summary>ENI, DISI or HDEF inside an interrupt routine (END there is <see cref="WrongBlockKind"/>).</summary>
    public const string NotInInterruptRoutine = "AWL004";

    /// <summary>An instruction in a block kind it does not belong to: CRET outside a subroutine, CRETI outside an interrupt routine, END outside OB1.</summary>
    public const string WrongBlockKind = "AWL005";

    /// <summary>ATCH, DTCH or CEVNT with an interrupt event the CPU does not have.</summary>
    public const string EventNotOnCpu = "AWL006";

    /// <summary>S, R, SI or RI with N = 0 (N is 1-255).</summary>
    public const string CountIsZero = "AWL007";

    /// <summary>An operand of a kind or size the instruction does not take (a byte for MOVW, a constant as OUT, AQW as IN).</summary>
    public const string OperandKind = "AWL008";

    /// <summary>Too many or too few operands.</summary>
    public const string OperandCount = "AWL009";

    /// <summary>A constant or number outside its range: label 256, port 1 on a one-port CPU, T256, LDS 9.</summary>
    public const string OutOfRange = "AWL010";

    /// <summary>An instruction of CPU firmware 2.0 and later (strings, TODRX, CEVNT ...) on an early CPU.</summary>
    public const string NeedsFirmware2 = "AWL011";

    /// <summary>A block header without its name (<c>ORGANIZATION_BLOCK OB1</c>): Micro/WIN writes NAME:OB1 (<see cref="AwlExportCheck"/>).</summary>
    public const string BlockHeaderWithoutName = "AWL012";

    /// <summary>A CALL or ATCH naming a subroutine or interrupt routine that is not in the file.</summary>
    public const string BlockNotInFile = "AWL013";

    /// <summary>Two blocks of one kind with the same number, or two blocks with the same name.</summary>
    public const string BlockDefinedTwice = "AWL014";

    /// <summary>Warning, not a refusal: a password-protected POU, exported without its code (<see cref="AwlBlock.IsPasswordProtected"/>).</summary>
    public const string ProtectedBlock = "AWL015";
}
