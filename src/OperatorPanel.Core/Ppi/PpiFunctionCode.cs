namespace OperatorPanel.Core.Ppi;

/// <summary>
/// The FDL frame control byte FC (PROFIBUS, felser.ch "Function code"; docs/ppi.md section 3). Bit 6 = request;
/// in a request bit 5 = FCB (frame count bit) and bit 4 = FCV (FCB valid), bits 0-3 the function; in a response bits
/// 4-5 the station type and bits 0-3 the answer.
/// </summary>
public static class PpiFunctionCode
{
    public const byte RequestBit = 0x40;
    public const byte FrameCountBit = 0x20;
    public const byte FrameCountValid = 0x10;

    /// <summary>Send and Request Data, low priority: what every PPI master in our sources sends.</summary>
    public const byte SendRequestDataLow = 0x0C;

    /// <summary>Send and Request Data, high priority.</summary>
    public const byte SendRequestDataHigh = 0x0D;

    /// <summary>Response "DL, data low" from a slave: the S7-200's response frame carries FC 16#08 (captures, docs/ppi.md).</summary>
    public const byte ResponseDataLow = 0x08;

    /// <summary>Response "DH, data high".</summary>
    public const byte ResponseDataHigh = 0x0A;

    /// <summary>
    /// The first request of an exchange: SRD low with FCB = 1 and FCV = 0, 16#6C (libnodave _daveExchangePPI,
    /// HslCommunication SiemensPPI). FCV = 0 starts a new frame-count sequence at the slave (PROFIBUS spec part 4 p. 131).
    /// </summary>
    public const byte FirstRequest = RequestBit | FrameCountBit | SendRequestDataLow;

    /// <summary>SRD low with FCV = 1 and the given FCB: 16#5C (FCB 0) or 16#7C (FCB 1), the master's polls.</summary>
    public static byte Poll(bool frameCountBit) =>
        (byte)(RequestBit | FrameCountValid | SendRequestDataLow | (frameCountBit ? FrameCountBit : 0));

    public static bool IsRequest(byte functionCode) => (functionCode & RequestBit) != 0;

    /// <summary>SRD low or high: the request that expects data back.</summary>
    public static bool IsSendRequestData(byte functionCode) =>
        IsRequest(functionCode) && (functionCode & 0x0F) is SendRequestDataLow or SendRequestDataHigh;

    public static bool HasValidFrameCount(byte functionCode) => (functionCode & FrameCountValid) != 0;

    public static bool FrameCount(byte functionCode) => (functionCode & FrameCountBit) != 0;

    /// <summary>A response carrying data: DL or DH (any station type bits).</summary>
    public static bool IsDataResponse(byte functionCode) =>
        !IsRequest(functionCode) && (functionCode & 0x0F) is ResponseDataLow or ResponseDataHigh;
}
