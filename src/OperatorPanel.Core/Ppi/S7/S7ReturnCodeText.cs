namespace OperatorPanel.Core.Ppi.S7;

/// <summary>The per-item return codes in our words.</summary>
public static class S7ReturnCodeText
{
    /// <summary>The code in our words, for messages ("VB9000: the address is beyond the CPU's memory (16#05)").</summary>
    public static string Describe(S7ReturnCode code) => code switch
    {
        S7ReturnCode.Success => "done",
        S7ReturnCode.HardwareFault => "hardware fault: no data from the I/O module (16#01)",
        S7ReturnCode.AccessDenied => "access not allowed or no such object on this CPU (16#03)",
        S7ReturnCode.AddressOutOfRange => "the address is beyond the CPU's memory (16#05)",
        S7ReturnCode.DataTypeNotSupported => "data type not supported (16#06)",
        S7ReturnCode.DataTypeInconsistent => "the data does not fit the item's size (16#07)",
        S7ReturnCode.ObjectDoesNotExist => "the object does not exist (16#0A)",
        _ => $"unknown answer 16#{(byte)code:X2}",
    };
}
