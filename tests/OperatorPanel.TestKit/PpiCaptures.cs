using OperatorPanel.Core.Ppi;

namespace OperatorPanel.TestKit;

/// <summary>
/// PPI telegrams published by others, used as test vectors (facts, not code; docs/ppi.md section 10 lists them). Each
/// is a whole telegram as hex; the FCS and lengths were checked when they were copied. PC = address 0, CPU = 2.
/// </summary>
public static class PpiCaptures
{
    /// <summary>HslCommunication SiemensPPI.cs (executeConfirm), also in several others: the poll, SD1 2 &lt;- 0 FC 5C.</summary>
    public const string Poll = "10 02 00 5C 5E 16";

    /// <summary>blueskit/siemens-s7-ppi-monitor ProgramTestPpi.cs s01: read VB300, 12 bytes, PDU reference 16#2658, FC 7C.</summary>
    public const string ReadVb300Request = """
        68 1B 1B 68 02 00 7C            // SD2, LE 27, CPU 2 <- PC 0, SRD FCB 1 FCV 1
        32 01 00 00 26 58 00 0E 00 00   // job, reference 2658, 14 parameter bytes, no data
        04 01                           // read, 1 item
        12 0A 10 02 00 0C 00 01 84 00 09 60   // bytes x12, DB 1, V, bit address 2400 = VB300
        6A 16
        """;

    /// <summary>The CPU's answer to <see cref="ReadVb300Request"/> (same capture, s02).</summary>
    public const string ReadVb300Answer = """
        68 21 21 68 00 02 08            // SD2, LE 33, PC 0 <- CPU 2, response DL
        32 03 00 00 26 58 00 02 00 10 00 00   // ack data, reference 2658, 2 parameter bytes, 16 data bytes, no error
        04 01                           // read, 1 item
        FF 04 00 60                     // success, length in bits: 96 = 12 bytes
        43 6C 99 B2 43 15 80 0B 43 33 66 76
        66 16
        """;

    /// <summary>Same capture, s03: a 7-item read (IB0-IB1, QB0, MB0, MB10, VB100, VB110, VD200), reference 16#2659.</summary>
    public const string ReadSevenItemsRequest = """
        68 63 63 68 02 00 7C
        32 01 00 00 26 59 00 56 00 00   // 86 parameter bytes = 2 + 7 x 12
        04 07
        12 0A 10 02 00 02 00 00 81 00 00 00   // IB0, 2 bytes
        12 0A 10 02 00 01 00 00 82 00 00 00   // QB0
        12 0A 10 02 00 01 00 00 83 00 00 00   // MB0
        12 0A 10 02 00 01 00 00 83 00 00 50   // MB10 (bit address 80)
        12 0A 10 02 00 01 00 01 84 00 03 20   // VB100
        12 0A 10 02 00 01 00 01 84 00 03 70   // VB110
        12 0A 10 02 00 04 00 01 84 00 06 40   // VB200, 4 bytes
        A2 16
        """;

    /// <summary>The answer to <see cref="ReadSevenItemsRequest"/> (s04): odd items padded with one byte, the last one not.</summary>
    public const string ReadSevenItemsAnswer = """
        68 3D 3D 68 00 02 08
        32 03 00 00 26 59 00 02 00 2C 00 00
        04 07
        FF 04 00 10 00 00               // IB0-IB1
        FF 04 00 08 09 00               // QB0 = 09, pad
        FF 04 00 08 00 00               // MB0, pad
        FF 04 00 08 00 00               // MB10, pad
        FF 04 00 08 00 00               // VB100, pad
        FF 04 00 08 00 00               // VB110, pad
        FF 04 00 20 00 47 00 6E         // VD200, last: no pad
        22 16
        """;

    /// <summary>Same capture, s91: write VD300 = 16#45208000, reference 16#2734, and the CPU's answer.</summary>
    public const string WriteVd300Request = """
        68 23 23 68 02 00 7C
        32 01 00 00 27 34 00 0E 00 08   // 14 parameter bytes, 8 data bytes
        05 01                           // write, 1 item
        12 0A 10 02 00 04 00 01 84 00 09 60   // bytes x4, V, bit address 2400 = VB300
        00 04 00 20 45 20 80 00         // reserved, length in bits 32, the value
        51 16
        """;

    public const string WriteVd300Answer = "68 12 12 68 00 02 08 32 03 00 00 27 34 00 02 00 01 00 00 05 01 FF A2 16";

    /// <summary>iot-tree PPIMsgRespR.java comment: the answer to a read of Q0.1 (bit item, size 16#03, length 1 bit) = 1.</summary>
    public const string ReadQ01Answer = "68 16 16 68 00 02 08 32 03 00 00 00 00 00 02 00 05 00 00 04 01 FF 03 00 01 01 4F 16";

    /// <summary>iot-tree PPIMsgReqRTC.java comment: read T32-T34 (size and area 16#1F, address = timer number) and the answer, 5 bytes per timer.</summary>
    public const string ReadTimersRequest = "68 1B 1B 68 02 00 6C 32 01 00 00 00 00 00 0E 00 00 04 01 12 0A 10 1F 00 03 00 00 1F 00 00 20 41 16";

    public const string ReadTimersAnswer = """
        68 24 24 68 00 02 08 32 03 00 00 00 00 00 02 00 13 00 00 04 01
        FF 09 00 0F                     // success, length in bytes: 15
        02 00 00 7F FF  00 00 00 00 00  00 00 00 00 00
        F0 16
        """;

    /// <summary>iot-tree PPIMsgReqRunStop.java comment (HslCommunication SiemensPPI.Stop sends the same): STOP and its answer.</summary>
    public const string StopRequest = "68 1D 1D 68 02 00 6C 32 01 00 00 00 00 00 10 00 00 29 00 00 00 00 00 09 50 5F 50 52 4F 47 52 41 4D AA 16";

    public const string StopAnswer = "68 10 10 68 00 02 08 32 03 00 00 00 00 00 01 00 00 00 00 29 69 16";

    /// <summary>HslCommunication SiemensPPI.Start and iot-tree: RUN ("P_PROGRAM" with 16#28).</summary>
    public const string RunRequest = "68 21 21 68 02 00 6C 32 01 00 00 00 00 00 14 00 00 28 00 00 00 00 00 00 FD 00 00 09 50 5F 50 52 4F 47 52 41 4D AA 16";

    /// <summary>A telegram given as hex, read by Core's reader; throws when it is not one whole sound telegram.</summary>
    public static PpiFrame Frame(string telegram)
    {
        var reader = new PpiFrameReader();
        reader.Append(Hex.Parse(telegram));
        return reader.TryTake(out var result) && result.Frame is { } frame && !reader.TryTake(out _)
            ? frame
            : throw new FormatException($"not one sound PPI telegram: {telegram}");
    }

    /// <summary>The S7 PDU inside an SD2 telegram given as hex.</summary>
    public static byte[] Pdu(string telegram) => [.. Frame(telegram).Data];
}
