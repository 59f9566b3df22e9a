using System.Collections.ObjectModel;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.ViewModels.Session;

namespace OperatorPanel.ViewModels.Inputs;

/// <summary>Builds the byte groups of the Inputs or Outputs window and routes the session's value changes to their lamps.</summary>
internal sealed class IoPointMap<T>(PanelSession session, Func<ProjectStation, IEnumerable<IoSymbol>> symbolsOf, Func<ProjectStation, IoSymbol, T> create)
    where T : IoPointViewModel
{
    private readonly Dictionary<WatchedItem, T> _points = [];

    public ObservableCollection<IoByteGroup<T>> Groups { get; } = [];

    public IEnumerable<T> Points => _points.Values;

    public void Rebuild()
    {
        _points.Clear();
        Groups.Clear();
        foreach (var station in session.Project.Stations)
        {
            foreach (var bytes in symbolsOf(station).GroupBy(s => s.Address.ByteOffset).OrderBy(g => g.Key))
            {
                var points = bytes.OrderBy(s => s.Address.Bit).Select(s => create(station, s)).ToList();
                points.ForEach(p => _points[new WatchedItem(p.Station, p.PlcAddress)] = p);
                var first = bytes.First().Address;
                Groups.Add(new IoByteGroup<T>(station.Name, PlcAddress.ForBytes(first.Area, first.ByteOffset, AccessWidth.Byte).ToString(), points));
            }
        }

        ReadAll();
    }

    public void Apply(ValuesChangedEventArgs e)
    {
        if (e.Reset)
        {
            ReadAll();
            return;
        }

        foreach (var change in e.Changes)
        {
            if (_points.TryGetValue(new WatchedItem(change.Station, change.Address), out var point))
            {
                point.Apply(change.Current);
            }
        }
    }

    private void ReadAll()
    {
        foreach (var point in _points.Values)
        {
            session.TryGetValue(point.Station, point.PlcAddress, out var value);
            point.Apply(value);
        }
    }
}
