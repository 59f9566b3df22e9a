using OperatorPanel.Stl.Instructions;

namespace OperatorPanel.Simulator.Stl;

/// <summary>The simulator's operand type for one operand of the Core instruction table.</summary>
internal static class StlOperandTypes
{
    public static StlOperandType Of(StlOperandSpec spec) => spec.Type switch
    {
        StlDataType.Label => StlOperandType.Label,
        StlDataType.Subroutine or StlDataType.InterruptRoutine => StlOperandType.Block,
        StlDataType.Event => StlOperandType.Event,
        StlDataType.Port => StlOperandType.Port,
        StlDataType.Timer => StlOperandType.Timer,
        StlDataType.Counter => StlOperandType.Counter,
        StlDataType.Bool => spec.Access == StlAccess.Read ? StlOperandType.BitIn : StlOperandType.BitOut,
        StlDataType.Byte or StlDataType.String or StlDataType.Word or StlDataType.Int or StlDataType.DWord or StlDataType.DInt
            or StlDataType.Real => Sized(spec),
    };

    /// <summary>Memory without accumulator or constant is an area a block instruction starts at (BMB IN, RCV TBL).</summary>
    private static StlOperandType Sized(StlOperandSpec spec)
    {
        var isArea = (spec.Kinds & (StlOperandKinds.AC | StlOperandKinds.Constant)) == 0;
        var read = spec.Access == StlAccess.Read;
        return (spec.Bytes, isArea, read) switch
        {
            (1, true, _) => StlOperandType.ByteArea,
            (2, true, _) => StlOperandType.WordArea,
            (4, true, _) => StlOperandType.DWordArea,
            (1, false, true) when spec.Min < 0 => StlOperandType.SignedByteIn,
            (1, false, true) => StlOperandType.ByteIn,
            (1, false, false) => StlOperandType.ByteOut,
            (2, false, true) => StlOperandType.WordIn,
            (2, false, false) => StlOperandType.WordOut,
            (_, false, true) => StlOperandType.DWordIn,
            _ => StlOperandType.DWordOut,
        };
    }
}
