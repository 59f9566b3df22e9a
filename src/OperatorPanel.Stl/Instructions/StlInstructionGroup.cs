namespace OperatorPanel.Stl.Instructions;

/// <summary>The sections of the manual's chapter 6 "S7-200 instruction set" an instruction belongs to.</summary>
public enum StlInstructionGroup
{
    BitLogic,
    Clock,
    Communication,
    Compare,
    Conversion,
    Counter,
    HighSpeed,
    IntegerMath,
    RealMath,
    Pid,
    Interrupt,
    Logic,
    Move,
    ProgramControl,
    ShiftRotate,
    String,
    Table,
    Timer,
    Subroutine,
}
