using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Ppi.S7;

namespace OperatorPanel.Core.Ppi;

/// <summary>
/// What PPI tells about a CPU without a program of ours (docs/ppi.md section 9): SMB6, the CPU identification byte (CPU
/// type in bits 4-7, ML801761 p. 498 Table D-7), SM0.7 the mode switch at RUN (off at TERM, seed 002 Table C-1), and
/// SMW22, SMW24, SMW26 the last, minimum and maximum scan time in ms (seed 002 Table C-9). RUN or STOP is not among
/// them: no source gives a PPI query for it, so it stays unknown.
/// </summary>
public sealed record PpiIdentity(Station Station, byte Smb6, bool SwitchAtRun, int LastScanMs, int MinScanMs, int MaxScanMs)
{
    /// <summary>One job of three SM items: SMB0 (SM0.7), SMB6, SMB22-SMB27.</summary>
    public static ImmutableArray<S7Item> Items { get; } = [S7Item.Bytes(S7Area.SM, 0, 1), S7Item.Bytes(S7Area.SM, 6, 1), S7Item.Bytes(S7Area.SM, 22, 6)];

    /// <summary>The identity from the answers to <see cref="Items"/>; null with the reason when an item was refused.</summary>
    public static PpiIdentity? From(Station station, IReadOnlyList<S7ItemResult> results, out string? error)
    {
        ArgumentNullException.ThrowIfNull(results);
        for (var i = 0; i < Items.Length; i++)
        {
            if (i >= results.Count || !results[i].Succeeded || results[i].Data.Length != Items[i].DataLength)
            {
                error = $"{station} did not give {Items[i]}: {(i < results.Count ? S7ReturnCodeText.Describe(results[i].Code) : "no item in the answer")}";
                return null;
            }
        }

        var scans = results[2].Data;
        error = null;
        return new PpiIdentity(station, results[1].Data[0], (results[0].Data[0] & 0x80) != 0, Word(scans, 0), Word(scans, 2), Word(scans, 4));
    }

    private static int Word(ImmutableArray<byte> data, int at) => (data[at] << 8) | data[at + 1];
}
