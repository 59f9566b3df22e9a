using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Ppi;

/// <summary>
/// The read jobs that cover a set of addresses (<see cref="PpiReadPlanner"/>), and where each address's bytes are.
/// Addresses that cannot be read over PPI are in <see cref="Rejected"/> with the reason.
/// </summary>
public sealed record PpiReadPlan(
    ImmutableArray<PpiReadRequest> Requests,
    ImmutableDictionary<PlcAddress, PpiSlice> Slices,
    ImmutableDictionary<PlcAddress, string> Rejected)
{
    public int DataBytes => Requests.Sum(r => r.DataBytes);
}
