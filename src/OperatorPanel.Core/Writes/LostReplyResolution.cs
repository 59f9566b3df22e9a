using System.Collections.Immutable;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Writes;

/// <summary>
/// Settles a write whose reply was lost by what the target holds now: the new value (confirmed), the old value (not
/// applied), anything else or nothing (unknown). The write is never repeated: the PLC may have acted.
/// </summary>
internal static class LostReplyResolution
{
    /// <summary>The READ of the target's bytes: the whole byte for a bit.</summary>
    public static ReadRequest ReadBackOf(WriteRequest request)
    {
        ArgumentNullException.ThrowIfNull(request);
        var area = ProtocolAreaExtensions.FromMemoryArea(request.Address.Area)!.Value;
        var length = request.BitValue is null ? request.Data.Length : 1;
        return new ReadRequest(request.Station, [new ReadItem(area, request.Address.ByteOffset, length)]);
    }

    /// <summary>
    /// Judges the read-back <paramref name="bytes"/> (the whole byte for a bit) against the new value and
    /// <paramref name="oldValue"/> (the last polled value; default when unknown).
    /// </summary>
    public static WriteOutcome Judge(WriteRequest request, ImmutableArray<byte> oldValue, ImmutableArray<byte> bytes, string cause)
    {
        ArgumentNullException.ThrowIfNull(request);
        var now = ValueStore.Extract(request.Address, bytes.AsSpan());
        if (now.AsSpan().SequenceEqual(request.Value.AsSpan()))
        {
            return new WriteOutcome.ConfirmedByReadBack(now, cause);
        }

        if (!oldValue.IsDefault && now.AsSpan().SequenceEqual(oldValue.AsSpan()))
        {
            return new WriteOutcome.NotApplied(now, cause);
        }

        var detail = oldValue.IsDefault
            ? $"the PLC holds {WriteLog.Format(request.Address, now)}, not the new value, and its old value was never read"
            : $"the PLC holds {WriteLog.Format(request.Address, now)}, neither the old {WriteLog.Format(request.Address, oldValue)} nor the new value: its program may have changed it";
        return new WriteOutcome.Unknown(now, cause, detail);
    }

    /// <summary>The read-back failed too: nothing is known.</summary>
    public static WriteOutcome Unresolved(string cause, string readBackFailure) =>
        new WriteOutcome.Unknown(default, cause, $"the read-back failed too ({readBackFailure})");
}
